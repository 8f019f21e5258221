package org.ripv.messages;

import java.util.List;

/** The registered services ({@code ?services}). */
public record ServiceList(List<ServiceDescriptor> services) implements Result {
    public ServiceList {
        services = List.copyOf(services);
    }
}
