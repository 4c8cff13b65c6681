// The local page of a live session (http_page.hpp): the report's styling, a script that fetches
// /latest.json every second and shows the document as tables, and each numeric column of a
// table of items (steps, windows, antennas) as a small plot over the items. Text from the
// document is set as text (textContent), never as markup.

#include "dynpos/io/markup.hpp"
#include "dynpos/live/http_page.hpp"

namespace dynpos::live {
namespace {

constexpr const char* kStyle =
    "body{font-family:sans-serif;margin:2em;max-width:70em}table{border-collapse:collapse;"
    "margin:0.5em 0}td,th{border:1px solid #ccc;padding:0.3em 0.6em;text-align:right}"
    "td:first-child,th:first-child{text-align:left}svg{border:1px solid #ccc;margin:0.2em}"
    ".state{color:#555}.final{color:#070;font-weight:bold}";

constexpr const char* kScript = R"JS(
const el = (tag, text) => { const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text; return e; };
const show = v => v === null ? '—' : typeof v === 'number' ? String(+v.toPrecision(6))
  : typeof v === 'object' ? JSON.stringify(v) : String(v);
const scalar = v => v === null || typeof v !== 'object';
function flat(o, p, out) { for (const [k, v] of Object.entries(o)) {
  if (v && typeof v === 'object' && !Array.isArray(v)) flat(v, p + k + '.', out);
  else if (scalar(v)) out[p + k] = v; } return out; }
function plot(name, ys) { const w = 220, h = 80, s = 'http://www.w3.org/2000/svg';
  const v = ys.filter(y => typeof y === 'number'); if (v.length < 2) return null;
  const lo = Math.min(...v), hi = Math.max(...v), d = hi - lo || 1;
  const svg = document.createElementNS(s, 'svg'); svg.setAttribute('width', w);
  svg.setAttribute('height', h + 16); const t = document.createElementNS(s, 'text');
  t.setAttribute('x', 4); t.setAttribute('y', 12); t.setAttribute('font-size', 11);
  t.textContent = name + ' (' + show(lo) + ' … ' + show(hi) + ')'; svg.appendChild(t);
  const pts = ys.map((y, i) => typeof y !== 'number' ? null :
    [4 + i * (w - 8) / Math.max(ys.length - 1, 1), 16 + h - 4 - (y - lo) / d * (h - 8)]);
  for (const p of pts) if (p) { const c = document.createElementNS(s, 'circle');
    c.setAttribute('cx', p[0]); c.setAttribute('cy', p[1]); c.setAttribute('r', 2.5);
    svg.appendChild(c); }
  const line = document.createElementNS(s, 'polyline'); line.setAttribute('fill', 'none');
  line.setAttribute('stroke', '#36c');
  line.setAttribute('points', pts.filter(p => p).map(p => p.join(',')).join(' '));
  svg.appendChild(line); return svg; }
function items(name, rows, into) { into.appendChild(el('h3', name));
  const flats = rows.map(r => flat(r, '', {})); const keys = [];
  for (const f of flats) for (const k of Object.keys(f)) if (!keys.includes(k)) keys.push(k);
  const table = el('table'), head = el('tr'); for (const k of keys) head.appendChild(el('th', k));
  table.appendChild(head); for (const f of flats) { const tr = el('tr');
    for (const k of keys) tr.appendChild(el('td', show(k in f ? f[k] : null)));
    table.appendChild(tr); } into.appendChild(table);
  const plots = el('div'); for (const k of keys) { const p = plot(k, flats.map(f => f[k]));
    if (p) plots.appendChild(p); } into.appendChild(plots); }
function render(doc, into, depth) { const table = el('table'); let rows = 0;
  for (const [k, v] of Object.entries(doc)) { if (scalar(v)) { const tr = el('tr');
      tr.appendChild(el('td', k)); tr.appendChild(el('td', show(v))); table.appendChild(tr);
      rows++; } }
  if (rows) into.appendChild(table);
  for (const [k, v] of Object.entries(doc)) {
    if (Array.isArray(v) && v.length && v.every(x => x && typeof x === 'object')) items(k, v, into);
    else if (Array.isArray(v)) { if (v.length) { const p = el('p', k + ': ' + v.map(show).join(', '));
      into.appendChild(p); } }
    else if (v && typeof v === 'object' && depth < 3) { into.appendChild(el('h3', k));
      render(v, into, depth + 1); } } }
async function refresh() { try { const r = await fetch('latest.json', {cache: 'no-store'});
    const doc = await r.json(); const state = document.getElementById('state');
    state.textContent = doc.final === undefined ? 'waiting for the first result' :
      (doc.final ? 'final' : 'live') + ', stream time ' + show(doc.stream_time_s) + ' s';
    state.className = doc.final ? 'final' : 'state';
    const out = document.getElementById('doc'); out.replaceChildren(); render(doc, out, 0);
  } catch (e) { document.getElementById('state').textContent = 'no answer: ' + e; } }
refresh(); setInterval(refresh, 1000);
)JS";

}  // namespace

std::string live_page_html(const std::string& title) {
  const std::string t = io::escape_markup(title);
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + t +
         "</title>\n<style>" + kStyle + "</style></head>\n<body><h1>" + t +
         "</h1>\n<p id=\"state\" class=\"state\">loading</p>\n<div id=\"doc\"></div>\n<script>" +
         kScript + "</script></body></html>\n";
}

}  // namespace dynpos::live
