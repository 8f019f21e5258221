package org.ripv.testing;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.annotation.Annotation;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.ClassDescriptor;
import org.junit.jupiter.api.ClassOrdererContext;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.parallel.Isolated;
import org.junit.jupiter.api.parallel.ResourceLock;
import org.junit.platform.commons.support.AnnotationSupport;

class LongestFirstTest {
    @ResourceLock("browser") static final class BrowserLong {}
    @ResourceLock("browser") static final class BrowserMid {}
    @ResourceLock("browser") static final class BrowserShort {}
    @ResourceLock("cpu") static final class CpuLong {}
    @Isolated static final class Alone {}
    static final class FreeLong {}
    static final class FreeShort {}
    static final class FreeTiny {}
    static final class FreeUnknown {}
    static final class Tiny1 {}
    static final class Tiny2 {}
    static final class Tiny3 {}
    static final class Tiny4 {}
    static final class Tiny5 {}
    static final class Tiny6 {}

    private final LongestFirst orderer = new LongestFirst(Map.ofEntries(
            Map.entry(BrowserLong.class.getName(), 95.0), Map.entry(BrowserMid.class.getName(), 70.0),
            Map.entry(BrowserShort.class.getName(), 5.0), Map.entry(CpuLong.class.getName(), 190.0),
            Map.entry(Alone.class.getName(), 30.0), Map.entry(FreeLong.class.getName(), 88.0),
            Map.entry(FreeShort.class.getName(), 12.0), Map.entry(FreeTiny.class.getName(), 0.1),
            Map.entry(Tiny1.class.getName(), 1.0), Map.entry(Tiny2.class.getName(), 1.0), Map.entry(Tiny3.class.getName(), 1.0),
            Map.entry(Tiny4.class.getName(), 1.0), Map.entry(Tiny5.class.getName(), 1.0), Map.entry(Tiny6.class.getName(), 1.0)));

    /** The listed ones average 35.4 s: a free class is long from 70.9 s, one not listed counts 35.4 s. */
    @Test
    void isolatedThenLongAndLockedLongestFirstThenTheRestShortestFirst() {
        assertThat(order(Tiny4.class, FreeTiny.class, BrowserShort.class, Tiny1.class, FreeUnknown.class, Alone.class,
                Tiny6.class, FreeShort.class, BrowserMid.class, Tiny2.class, CpuLong.class, Tiny5.class, FreeLong.class,
                BrowserLong.class, Tiny3.class))
                .containsExactly(Alone.class, CpuLong.class, BrowserLong.class, FreeLong.class, BrowserMid.class,
                        BrowserShort.class, FreeTiny.class, Tiny1.class, Tiny2.class, Tiny3.class, Tiny4.class, Tiny5.class,
                        Tiny6.class, FreeShort.class, FreeUnknown.class);
    }

    @Test
    void twoOfOneLockFollowEachOtherOnlyWhenNothingElseIsLeft() {
        assertThat(order(BrowserShort.class, BrowserMid.class, BrowserLong.class, CpuLong.class))
                .containsExactly(CpuLong.class, BrowserLong.class, BrowserMid.class, BrowserShort.class);
        assertThat(order(BrowserMid.class, BrowserLong.class, FreeLong.class, FreeTiny.class, Tiny1.class, Tiny2.class))
                .containsExactly(BrowserLong.class, FreeLong.class, BrowserMid.class, FreeTiny.class, Tiny1.class, Tiny2.class);
    }

    /**
     * The three browser classes take 170 s one after another: more than FreeLong's 88 s, less than
     * CpuLong's 190 s. Longest first alone would start FreeLong before every browser class.
     */
    @Test
    void aLocksClassesCountTogetherSoThatTheLongestChainStartsFirst() {
        LongestFirst chained = new LongestFirst(Map.ofEntries(
                Map.entry(BrowserLong.class.getName(), 65.0), Map.entry(BrowserMid.class.getName(), 55.0),
                Map.entry(BrowserShort.class.getName(), 50.0), Map.entry(CpuLong.class.getName(), 190.0),
                Map.entry(FreeLong.class.getName(), 88.0), Map.entry(FreeTiny.class.getName(), 0.1),
                Map.entry(Tiny1.class.getName(), 1.0), Map.entry(Tiny2.class.getName(), 1.0), Map.entry(Tiny3.class.getName(), 1.0),
                Map.entry(Tiny4.class.getName(), 1.0), Map.entry(Tiny5.class.getName(), 1.0), Map.entry(Tiny6.class.getName(), 1.0)));
        assertThat(order(chained, FreeLong.class, BrowserShort.class, Tiny2.class, FreeTiny.class, BrowserMid.class,
                Tiny1.class, CpuLong.class, Tiny3.class, BrowserLong.class, Tiny4.class, Tiny5.class, Tiny6.class))
                .as("CpuLong 190 s, the browser chain 170 s, FreeLong 88 s; the chain's next 105 s must wait for another lock")
                .containsExactly(CpuLong.class, BrowserLong.class, FreeLong.class, BrowserMid.class, BrowserShort.class,
                        FreeTiny.class, Tiny1.class, Tiny2.class, Tiny3.class, Tiny4.class, Tiny5.class, Tiny6.class);
        assertThat(order(chained, FreeLong.class, BrowserMid.class, BrowserLong.class, FreeTiny.class, Tiny1.class,
                Tiny2.class, Tiny3.class, Tiny4.class, Tiny5.class, Tiny6.class))
                .as("two browser classes (120 s together) still start before FreeLong; the second (55 s) after it")
                .containsExactly(BrowserLong.class, FreeLong.class, BrowserMid.class, FreeTiny.class, Tiny1.class,
                        Tiny2.class, Tiny3.class, Tiny4.class, Tiny5.class, Tiny6.class);
    }

    @Test
    void withoutTimesEveryClassCountsTheSameAndTheOrderIsStable() {
        LongestFirst blind = new LongestFirst(Map.of());
        List<Class<?>> first = order(blind, FreeShort.class, FreeLong.class, Alone.class, CpuLong.class);
        assertThat(first).as("the locked one first, the rest by name").containsExactly(Alone.class, CpuLong.class,
                FreeLong.class, FreeShort.class);
        assertThat(order(blind, CpuLong.class, Alone.class, FreeLong.class, FreeShort.class)).isEqualTo(first);
    }

    private List<Class<?>> order(Class<?>... classes) {
        return order(orderer, classes);
    }

    private static List<Class<?>> order(LongestFirst orderer, Class<?>... classes) {
        List<ClassDescriptor> descriptors = new ArrayList<>();
        for (Class<?> c : classes) {
            descriptors.add(new Descriptor(c));
        }
        orderer.orderClasses(new ClassOrdererContext() {
            @Override
            public List<? extends ClassDescriptor> getClassDescriptors() {
                return descriptors;
            }

            @Override
            public Optional<String> getConfigurationParameter(String key) {
                return Optional.empty();
            }
        });
        return descriptors.stream().<Class<?>>map(ClassDescriptor::getTestClass).toList();
    }

    private record Descriptor(Class<?> getTestClass) implements ClassDescriptor {
        @Override
        public String getDisplayName() {
            return getTestClass.getSimpleName();
        }

        @Override
        public boolean isAnnotated(Class<? extends Annotation> type) {
            return AnnotationSupport.isAnnotated(getTestClass, type);
        }

        @Override
        public <A extends Annotation> Optional<A> findAnnotation(Class<A> type) {
            return AnnotationSupport.findAnnotation(getTestClass, type);
        }

        @Override
        public <A extends Annotation> List<A> findRepeatableAnnotations(Class<A> type) {
            return AnnotationSupport.findRepeatableAnnotations(getTestClass, type);
        }
    }
}
