// A DataVisServer plot's numbers (ImageResult.chart, a ChartData) as an interactive uPlot chart:
// drag to zoom (double-click to zoom out), the values under the pointer, CSV and PNG of it.
import uPlot from '/webjars/uplot/1.6.30/dist/uPlot.esm.js';
import { csv } from './table.js';
import { utc, axisValues } from './time.js';

const num = (v) => (v == null || v === 'NaN' || Number.isNaN(Number(v)) ? null : Number(v));
const COLOURS = ['#0b5cad', '#cf222e', '#1a7f37', '#9a6700', '#8250df', '#bf3989'];

/** Whether every series has the first one's x values in ascending order (uPlot's usual mode). */
function aligned(series) {
  const x = series[0]?.x || [];
  for (let i = 1; i < x.length; i++) if (num(x[i]) < num(x[i - 1])) return false;
  return series.every((s) => s.x.length === x.length && s.x.every((v, i) => num(v) === num(x[i])));
}

function formatX(chart, v) {
  if (v == null) return '';
  return chart.kind === 'TIME' || chart.kind === 'DEPTH' ? utc(v) : String(v);
}

/** Draws the chart into host (emptied first); returns the uPlot. */
export function chartSize(host) {
  const width = Math.max(260, Math.min(host.clientWidth || 800, 1100));
  return { width, height: Math.round(Math.min(520, Math.max(240, width * 0.6))) };
}

export function drawChart(host, chart, readout) {
  host.replaceChildren();
  const series = chart.series || [];
  const time = chart.kind === 'TIME' || chart.kind === 'DEPTH';
  const down = chart.kind === 'DEPTH' || chart.kind === 'PROFILE';
  const { width, height } = chartSize(host);
  const scales = { x: { time }, y: { dir: down ? -1 : 1 } };
  const axes = [{ label: chart.xLabel, stroke: '#1b1f24' }, { label: chart.yLabel, stroke: '#1b1f24', size: 70 }];
  // Time ticks as every page writes time (UTC, 2026-11-28 / 05:40), not uPlot's local US dates.
  if (time) Object.assign(axes[0], { values: (u, ticks, ax, space, incr) => axisValues(ticks, incr), size: 56 });
  const opts = { width, height, ms: 1, scales, axes, title: chart.title, cursor: { drag: { x: true, y: true, uni: 30 } },
    hooks: { setCursor: [(u) => showValue(u, chart, readout)] } };
  if (time) opts.tzDate = (ms) => uPlot.tzDate(new Date(ms), 'Etc/UTC'); // the axis in UTC, as the data and the CSV are
  let data;
  if (aligned(series)) {
    opts.series = [{ label: chart.xLabel, value: (u, v) => formatX(chart, v) },
      ...series.map((s, i) => ({ label: s.unit ? `${s.name} (${s.unit})` : s.name, stroke: COLOURS[i % COLOURS.length], spanGaps: false }))];
    data = [(series[0]?.x || []).map(num), ...series.map((s) => s.y.map(num))];
  } else {
    // Tracks and profiles: x is not time-ordered, so each series is its own (x, y) list (uPlot's mode 2).
    opts.mode = 2;
    opts.scales.x.auto = true;
    opts.scales.y.auto = true;
    opts.series = [{}, ...series.map((s, i) => ({ label: s.unit ? `${s.name} (${s.unit})` : s.name, stroke: COLOURS[i % COLOURS.length],
      // every fix as a dot: uPlot's own point filter counts on time-ordered x, so name them all
      fill: null, points: { show: true, size: 5, fill: COLOURS[i % COLOURS.length], filter: (u, si) => u.data[si][0].map((_, k) => k) },
      facets: [{ scale: 'x', auto: true }, { scale: 'y', auto: true }] }))];
    opts.legend = { live: false };
    data = [null, ...series.map((s) => [s.x.map(num), s.y.map(num)])];
  }
  const u = new uPlot(opts, data, host);
  host.dataset.points = String(series.reduce((n, s) => n + s.x.length, 0));
  host.dataset.kind = chart.kind;
  return u;
}

// On screen a pointer's place needs no more digits than the axes show; the CSV keeps every digit.
const shown = (chart, v) => (typeof v === 'number' && !(chart.kind === 'TIME' || chart.kind === 'DEPTH') ? String(Number(v.toPrecision(8))) : formatX(chart, v));

// The pointer's place in the chart's own units: works for every kind, time-ordered or not.
function showValue(u, chart, readout) {
  if (!readout) return;
  const { left, top } = u.cursor;
  if (left == null || left < 0) { readout.textContent = ''; return; }
  const x = u.posToVal(left, 'x');
  const y = u.posToVal(top, 'y');
  let near = '';
  let best = Infinity;
  (chart.series || []).forEach((s) => s.x.forEach((sx, i) => {
    const px = u.valToPos(num(sx), 'x'), py = u.valToPos(num(s.y[i]), 'y');
    const d = (px - left) ** 2 + (py - top) ** 2;
    if (d < best && num(s.y[i]) != null) { best = d; near = `${s.name}: ${shown(chart, num(sx))}, ${num(s.y[i])}`; }
  }));
  readout.textContent = `pointer ${shown(chart, x)}, ${Number(y.toPrecision(7))}` + (best < 400 ? ` · nearest ${near}` : '');
}

/** The chart's numbers as CSV: one row per point, series, x and y (time as ISO UTC). */
export function chartCsv(chart) {
  const rows = [];
  // ISO 8601 with milliseconds in the file: for programs, not people.
  const iso = (v) => (v == null ? '' : chart.kind === 'TIME' || chart.kind === 'DEPTH' ? new Date(v).toISOString() : String(v));
  for (const s of chart.series || []) s.x.forEach((x, i) => rows.push([s.name, iso(num(x)), num(s.y[i]) ?? '']));
  return csv(['series', chart.xLabel || 'x', chart.yLabel || 'y'], rows);
}

/** The chart as a PNG: its canvas (axes included) under its title, on white. */
export function chartPng(u, title) {
  const src = u.ctx.canvas;
  const out = document.createElement('canvas');
  out.width = src.width;
  out.height = src.height + 40;
  const g = out.getContext('2d');
  g.fillStyle = '#fff';
  g.fillRect(0, 0, out.width, out.height);
  g.fillStyle = '#1b1f24';
  g.font = '20px sans-serif';
  g.fillText(title || '', 10, 28);
  g.drawImage(src, 0, 40);
  return new Promise((done) => out.toBlob(done, 'image/png'));
}
