// A MailBox's full address is <Service>::<host>HANDLE; people know a vehicle by its handle (glider1).
export function vehicleName(address) {
  const at = address.lastIndexOf('>');
  return at >= 0 && at < address.length - 1 ? address.substring(at + 1) : address;
}
