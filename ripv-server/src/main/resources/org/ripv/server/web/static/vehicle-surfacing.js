// The vehicle page's last call, trends and track (docs/surfacings.md#on-the-web-console): what `?surfacings MAILBOX
// --json --outlook` says, shown. The page asks again when the call's events come, or the dialog ends on its countdown.
import { surfacings, lastCall, TRENDS, trackFixes, waypointShort, abort } from './surfacing.js';
import { drawTrend } from './trend.js';
import { drawMap, currentLayer, waypointLayer } from './map.js';
import { PlanModel } from './plan-model.js';
import { gliderLayer } from './plan-layers.js';

const COLOURS = ['#0b5cad', '#1a7f37', '#cf222e', '#9a6700', '#8250df'];

export class SurfacingView {
  constructor(po, mailbox) {
    this.po = po;
    this.mailbox = mailbox;
    this.data = { records: [], outlook: null };
    this.plan = new PlanModel(); // the goto list the glider runs (?plan current), drawn on the track (docs/plans.md)
    this.timer = null;
    window.addEventListener('resize', () => { clearTimeout(this.resized); this.resized = setTimeout(() => this.draw(), 150); });
  }

  /** Asks again soon (several events of one call make one request). */
  soon(ms = 800) {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => this.refresh(), ms);
  }

  /** A console entry: an event of the call, or the dialog's countdown (the record is kept when it ends). */
  take(e) {
    if (e.kind === 'EVENT' || (e.kind === 'LINE' && /Hit Control-C within \d+/.test(e.text || ''))) this.soon();
  }

  async refresh() {
    const [d, plan] = await Promise.all([surfacings(this.po, this.mailbox), this.po.send('', `?plan ${this.mailbox} current`)
      .catch((e) => ({ status: 'ERROR', text: String(e) }))]);
    this.data = d;
    if (plan.status !== 'ERROR') this.plan.setCurrent(plan.result?.rows || [], plan.text.split('\n')[0]);
    this.draw();
    const host = document.getElementById('surfacing');
    host.dataset.records = String(d.records.length);
    host.dataset.ready = 'true';
    if (d.error) host.dataset.error = d.error;
  }

  draw() {
    const { records, outlook, error } = this.data;
    const last = records[records.length - 1];
    const dl = document.getElementById('last-call');
    const rows = error ? [['error', 'Call records', `not available: ${error}`]] : lastCall(last, outlook);
    dl.replaceChildren(...rows.flatMap(([key, label, text]) => {
      const dt = document.createElement('dt');
      dt.textContent = label;
      const dd = document.createElement('dd');
      dd.dataset.key = key;
      dd.textContent = text;
      if (key === 'abort' && abort(last)) dd.prepend(badge(abort(last).fresh ? 'abort' : 'abort old', abort(last).fresh ? 'new abort' : 'abort'), ' ');
      if (key === 'leak' && (last?.leak === true)) dd.prepend(badge('leak', 'leak'), ' ');
      return [dt, dd];
    }));
    const trends = document.getElementById('trends');
    const series = outlook?.series || { time_ms: [] };
    if (trends.childElementCount !== TRENDS.length) {
      trends.replaceChildren(...TRENDS.map(([key]) => Object.assign(document.createElement('canvas'), { id: `trend-${key}` })));
    }
    let drawn = 0;
    TRENDS.forEach(([key, title, unit], i) => {
      const c = document.getElementById(`trend-${key}`);
      c.setAttribute('role', 'img');
      drawTrend(c, series.time_ms || [], series[key] || [], title, unit, COLOURS[i % COLOURS.length]);
      if (Number(c.dataset.points) > 0) drawn++;
    });
    trends.dataset.series = String(drawn);
    const fixes = trackFixes(outlook);
    const wpt = outlook?.wpt_lat == null ? null : { lat: outlook.wpt_lat, lon: outlook.wpt_lon };
    const from = outlook?.fix_lat == null ? null : { lat: outlook.fix_lat, lon: outlook.fix_lon };
    const layers = [currentLayer(fixes.filter((p) => p.current_e != null))];
    if (wpt) layers.push(waypointLayer(from, wpt, waypointShort(outlook)));
    layers.unshift(gliderLayer(this.plan));
    const goto = this.plan.current.waypoints.map((p) => ({ lat: p.lat, lon: p.lon }));
    drawMap(document.getElementById('track'), [{ name: this.mailbox, track: fixes, also: [...(wpt ? [wpt] : []), ...goto] }], layers,
      this.mailbox);
  }
}

function badge(cls, text) {
  const b = document.createElement('span');
  b.className = `badge ${cls}`;
  b.textContent = text;
  return b;
}
