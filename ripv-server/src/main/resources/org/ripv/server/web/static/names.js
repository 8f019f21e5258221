// A MailBox's full address is <Service>::<host>HANDLE; people know a vehicle by its handle (glider1).
export function vehicleName(address) {
  const at = address.lastIndexOf('>');
  return at >= 0 && at < address.length - 1 ? address.substring(at + 1) : address;
}

/** Labels for a list of addresses: the handle, and the service's name too where two share a handle (TTY1 (ClockService)). */
export function labels(addresses) {
  const count = new Map();
  for (const a of addresses) count.set(vehicleName(a), (count.get(vehicleName(a)) || 0) + 1);
  return new Map(addresses.map((a) => {
    const name = vehicleName(a);
    const service = /^<([^>]*)>/.exec(a)?.[1];
    return [a, count.get(name) > 1 && service ? `${name} (${service})` : name];
  }));
}
