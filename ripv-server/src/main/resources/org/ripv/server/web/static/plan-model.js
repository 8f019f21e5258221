// The state of the plan page: the proposed goto list a pilot edits (waypoints and b_args), the list the glider runs as far
// as the shore knows (its last fetched goto file, the waypoint its last dialog steered for, its last fix), and the file
// the proposed list makes. The table and the map are two views of this one model: each edit goes through it, and every
// view redraws on its change events. No DOM here, so it is testable on its own.

export const DEFAULT_BARGS = [
  ['num_legs_to_run', 'nodim', '-1', 'loop'], ['start_when', 'enum', '0', 'BAW_IMMEDIATELY'],
  ['list_stop_when', 'enum', '7', 'BAW_WHEN_WPT_DIST'], ['initial_wpt', 'enum', '-2', '0 to N-1, -1 after the last achieved, -2 the closest'],
  ['num_waypoints', 'nodim', '0', ''],
];

/** Decimal degrees as Slocum's DDMM.mmmm, the sign in front. */
export function ddmm(deg) {
  const a = Math.abs(deg);
  let d = Math.floor(a);
  let m = (a - d) * 60;
  if (m >= 59.99995) { d += 1; m = 0; }
  return `${deg < 0 ? '-' : ''}${d}${m.toFixed(4).padStart(7, '0')}`;
}

/** Degrees as the table shows them: five decimals (about a metre). */
export const degrees = (v) => (Number.isFinite(v) ? v.toFixed(5) : '');

export class PlanModel {
  constructor() {
    /** The proposed list: { lat, lon, comment } with lat/lon as typed (text), so a bad entry stays visible until fixed. */
    this.waypoints = [];
    /** [name, units, value, comment] */
    this.bargs = DEFAULT_BARGS.map((b) => [...b]);
    /** What the glider runs: { source, waypoints: [{ n, lat, lon }], heading: { lat, lon } | null, fix: { lat, lon } | null }. */
    this.current = { source: '', waypoints: [], heading: null, fix: null };
    this.listeners = [];
  }

  /** f(what, from): what is 'waypoints', 'bargs' or 'current'; from is the view that made the change (it need not redraw). */
  onChange(f) { this.listeners.push(f); }

  emit(what, from) {
    if (what === 'waypoints') this.countWaypoints();
    for (const f of this.listeners) f(what, from);
  }

  /** num_waypoints is counted, never typed: the glider reads exactly this many lines. */
  countWaypoints() {
    const b = this.bargs.find((x) => x[0] === 'num_waypoints');
    if (b) b[2] = String(this.waypoints.length);
  }

  /** The proposed list from ?plan check's rows (n, lat, lon, comment) and b_args. */
  load(rows, bargs) {
    this.waypoints = rows.map(([, lat, lon, comment]) => ({ lat: String(lat), lon: String(lon), comment: comment ?? '' }));
    if (bargs?.length) this.bargs = bargs.map((b) => [...b]);
    this.emit('bargs');
    this.emit('waypoints');
  }

  add(lat = '', lon = '', comment = '', from = null) {
    this.waypoints.push({ lat: typeof lat === 'number' ? degrees(lat) : lat, lon: typeof lon === 'number' ? degrees(lon) : lon, comment });
    this.emit('waypoints', from);
  }

  /** A waypoint moved (dragged on the map): numbers in, kept to five decimals. */
  move(i, lat, lon, from = null) {
    const w = this.waypoints[i];
    if (!w) return;
    w.lat = degrees(Math.max(-90, Math.min(90, lat)));
    w.lon = degrees(((lon + 540) % 360) - 180);
    this.emit('waypoints', from);
  }

  /** A field typed in the table: 'lat', 'lon' or 'comment'. */
  edit(i, field, value, from = null) {
    const w = this.waypoints[i];
    if (!w || !['lat', 'lon', 'comment'].includes(field)) return;
    w[field] = value;
    this.emit('waypoints', from);
  }

  remove(i, from = null) {
    if (i < 0 || i >= this.waypoints.length) return;
    this.waypoints.splice(i, 1);
    this.emit('waypoints', from);
  }

  setBarg(name, field, value, from = null) {
    const b = this.bargs.find((x) => x[0] === name);
    if (!b || name === 'num_waypoints') return;
    b[field === 'comment' ? 3 : 2] = value;
    this.emit('bargs', from);
  }

  /** What the glider runs, from ?plan current's rows (kind, n, lat, lon, comment) and the reply's first line. */
  setCurrent(rows, source) {
    const num = (v) => Number(v);
    this.current = {
      source: source || '',
      waypoints: rows.filter((r) => r[0] === 'waypoint').map((r) => ({ n: Number(r[1]), lat: num(r[2]), lon: num(r[3]) })),
      heading: rows.filter((r) => r[0] === 'heading').map((r) => ({ lat: num(r[2]), lon: num(r[3]) }))[0] || null,
      fix: rows.filter((r) => r[0] === 'fix').map((r) => ({ lat: num(r[2]), lon: num(r[3]) }))[0] || null,
    };
    this.emit('current');
  }

  /** The proposed waypoints that are numbers, with their index: what the map can draw. */
  points() {
    return this.waypoints.map((w, i) => ({ i, lat: Number(w.lat), lon: Number(w.lon) }))
      .filter((p) => String(this.waypoints[p.i].lat).trim() !== '' && String(this.waypoints[p.i].lon).trim() !== ''
        && Number.isFinite(p.lat) && Number.isFinite(p.lon) && Math.abs(p.lat) <= 90 && Math.abs(p.lon) <= 180);
  }

  /** Every place the map should show ({ lat, lon }): the proposed and current lists, the heading and the fix. */
  extent() {
    const c = this.current;
    return [...this.points(), ...c.waypoints, ...(c.heading ? [c.heading] : []), ...(c.fix ? [c.fix] : [])]
      .map((p) => ({ lat: p.lat, lon: p.lon }));
  }

  /** The file the proposed list makes, as the glider reads it. */
  fileText(name, user, when) {
    const lines = ['behavior_name=goto_list', `# ${name} written in the RIPV web console by ${user} at ${when}`, '', '<start:b_arg>'];
    let counted = false;
    for (const [bname, units, value, comment] of this.bargs) {
      const v = bname === 'num_waypoints' ? String(this.waypoints.length) : String(value).trim();
      counted ||= bname === 'num_waypoints';
      lines.push(`\tb_arg: ${bname}(${units}) ${v}${comment.trim() ? ` # ${comment.trim()}` : ''}`);
    }
    if (!counted) lines.push(`\tb_arg: num_waypoints(nodim) ${this.waypoints.length}`);
    lines.push('<end:b_arg>', '<start:waypoints>', '# LON LAT');
    // a value that is not a number goes as typed: the server's check says where it is wrong
    const f = (v) => (String(v).trim() !== '' && Number.isFinite(Number(v)) ? ddmm(Number(v)) : (String(v).trim() || '?'));
    for (const w of this.waypoints) {
      lines.push(`${f(w.lon)}\t${f(w.lat)}${w.comment.trim() ? ` # ${w.comment.trim()}` : ''}`);
    }
    lines.push('<end:waypoints>', '');
    return lines.join('\n');
  }
}
