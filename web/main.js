// The page: draws what the board (alp85.wasm, web/binding.cpp) shows and hands it the user's
// keys, files and text. Every decision about the machine is the board's; this file only draws.
import createAlp85 from './alp85.js';
import { WALKTHROUGH } from './walkthrough.js';

const $ = (id) => document.getElementById(id);
const CLOCK_HZ = 3072000;
const FRAME_BUDGET_S = 0.010;  // host time the machine may take in one frame (60 fps leaves 16.7 ms)

const mod = await createAlp85();
const board = new mod.Board();

// ---- the display: eight seven-segment digits (a = bit 0 ... g = bit 6, dp = bit 7) -------------
const SEGMENTS = [  // polygons in a 44 x 72 box, a b c d e f g, then the dot
  '8,4 36,4 32,9 12,9', '37,6 37,34 33,32 33,10', '37,38 37,66 33,62 33,40', '8,68 36,68 32,63 12,63',
  '7,38 7,66 11,62 11,40', '7,6 7,34 11,32 11,10', '9,36 13,33 31,33 35,36 31,39 13,39',
];
const digits = [];
for (let i = 0; i < 8; i++) {
  const svg = document.createElementNS('http://www.w3.org/2000/svg', 'svg');
  svg.setAttribute('viewBox', '0 0 44 72');
  const segs = SEGMENTS.map((pts) => {
    const p = document.createElementNS('http://www.w3.org/2000/svg', 'polygon');
    p.setAttribute('points', pts);
    p.setAttribute('class', 'seg');
    svg.appendChild(p);
    return p;
  });
  const dp = document.createElementNS('http://www.w3.org/2000/svg', 'circle');
  dp.setAttribute('cx', 41); dp.setAttribute('cy', 67); dp.setAttribute('r', 3); dp.setAttribute('class', 'seg');
  svg.appendChild(dp);
  segs.push(dp);
  $('display').appendChild(svg);
  digits.push(segs);
}
let shown = [];
function drawDisplay() {
  const bytes = board.display();
  for (let i = 0; i < 8; i++) {
    if (bytes[i] === shown[i]) continue;
    digits[i].forEach((seg, bit) => seg.classList.toggle('on', (bytes[i] >> bit & 1) === 1));
  }
  shown = bytes;
  const text = board.displayText();
  const d = $('display');
  if (d.dataset.text !== text) { d.dataset.text = text; d.setAttribute('aria-label', `display: ${text}`); }
}

// ---- the keypad, laid out and captioned as the window's; the PC keys of its key map ------------
const keyButtons = new Map();
for (const k of board.keypad()) {
  const b = document.createElement('button');
  b.type = 'button';
  b.dataset.key = k.name;
  b.className = k.fn ? 'fn' : '';
  b.style.gridRow = k.row + 1;
  b.style.gridColumn = k.col + 1;
  b.append(k.cap);
  const hint = document.createElement('small');
  hint.textContent = `[${k.pc}]`;
  b.append(hint);
  const up = () => { if (b.classList.contains('down')) { board.key(k.name, false); b.classList.remove('down'); } };
  b.addEventListener('pointerdown', (e) => { e.preventDefault(); board.key(k.name, true); b.classList.add('down'); });
  b.addEventListener('pointerup', up);
  b.addEventListener('pointerleave', up);
  // A click without pointer events (keyboard activation, a test's synthetic click) presses and releases.
  b.addEventListener('click', (e) => { if (e.detail === 0) { board.key(k.name, true); board.key(k.name, false); } });
  $('keypad').appendChild(b);
  keyButtons.set(k.name, b);
}
for (const [keys, action] of board.keyMap()) {
  const tr = document.createElement('tr');
  tr.innerHTML = '<td></td><td></td>';
  tr.cells[0].textContent = keys;
  tr.cells[1].textContent = action;
  $('keymap').appendChild(tr);
}
const typing = (e) => ['TEXTAREA', 'INPUT', 'SELECT'].includes(e.target.tagName);
document.addEventListener('keydown', (e) => {
  if (typing(e) || e.ctrlKey || e.metaKey || e.altKey || e.repeat) return;
  const name = board.pcKey(e.key, true);
  if (name) { e.preventDefault(); keyButtons.get(name)?.classList.add('down'); }
});
document.addEventListener('keyup', (e) => {
  if (typing(e)) return;
  const name = board.pcKey(e.key, false);
  if (name) keyButtons.get(name)?.classList.remove('down');
});

// ---- the machine tool: X-Y table (ideal line, toolpath, tool), Z gauge, the axes' figures -------
const canvas = $('table');
const ctx = canvas.getContext('2d');
const path = [];  // x, y pairs in table mm
// Two canvases, one over the other: below, the grid and the toolpath, drawn once and extended as
// the path grows (redrawn whole only when the view moves); above, the ideal line and the tool,
// redrawn when they move. The browser composites them; nothing is copied between them.
const top = $('table-top');
const tctx = top.getContext('2d');
const lctx = ctx;
let bounds = null, view = null, drawnPoints = 0, lastKey = '';
function grow(x, y) {
  if (!bounds) bounds = { x0: x, x1: x, y0: y, y1: y };
  bounds.x0 = Math.min(bounds.x0, x); bounds.x1 = Math.max(bounds.x1, x);
  bounds.y0 = Math.min(bounds.y0, y); bounds.y1 = Math.max(bounds.y1, y);
}
function resetPath() { path.length = 0; bounds = null; view = null; drawnPoints = 0; lastKey = ''; }
function drawTable(st) {
  const n = board.pathSize();
  if (n < path.length / 2) resetPath();
  if (n > path.length / 2) {
    const more = board.pathSince(path.length / 2);
    for (let i = 0; i < more.length; i += 2) { path.push(more[i], more[i + 1]); grow(more[i], more[i + 1]); }
  }
  const line = board.ideal();
  const tx = st.axes[0].mm, ty = st.axes[1].mm;
  const key = `${n} ${tx} ${ty} ${line ? [line.x0, line.y0, line.x1, line.y1].join() : ''}`;
  if (key === lastKey) return;  // nothing moved: the picture stands
  lastKey = key;
  grow(0, 0); grow(tx, ty);
  if (line) { grow(line.x0, line.y0); grow(line.x1, line.y1); }
  const b = bounds;
  const span = Math.max(b.x1 - b.x0, (b.y1 - b.y0) * canvas.width / canvas.height, 20) * 1.15;
  const cx = (b.x0 + b.x1) / 2, cy = (b.y0 + b.y1) / 2;
  // The view's span is a 1-2-5 step at or above the picture's, centred on it: a growing path moves
  // the view now and then (when it leaves it), not every frame.
  const decade = 10 ** Math.floor(Math.log10(span));
  const vspan = [1, 2, 5, 10].map((m) => m * decade).find((v) => v >= span);
  const fits = view && span <= view.span && b.x0 >= view.cx - view.span / 2 && b.x1 <= view.cx + view.span / 2 &&
    b.y0 >= view.cy - view.span * canvas.height / canvas.width / 2 && b.y1 <= view.cy + view.span * canvas.height / canvas.width / 2;
  if (!fits) {
    view = { span: vspan, cx, cy };
    drawnPoints = 0;
  }
  const scale = canvas.width / view.span;
  const X = (x) => canvas.width / 2 + (x - view.cx) * scale;
  const Y = (y) => canvas.height / 2 - (y - view.cy) * scale;
  if (drawnPoints === 0) drawGrid();
  if (path.length / 2 > drawnPoints + 1 || (drawnPoints === 0 && path.length >= 4)) {
    const from = Math.max(0, drawnPoints - 1);
    lctx.strokeStyle = '#c0392b'; lctx.lineWidth = 2; lctx.lineJoin = 'round'; lctx.beginPath();
    lctx.moveTo(X(path[2 * from]), Y(path[2 * from + 1]));
    for (let i = 2 * (from + 1); i < path.length; i += 2) lctx.lineTo(X(path[i]), Y(path[i + 1]));
    lctx.stroke();
    drawnPoints = path.length / 2;
  }
  // above: the ideal line over the toolpath, so that both show where they coincide, and the tool
  tctx.clearRect(0, 0, top.width, top.height);
  if (line) {
    tctx.strokeStyle = '#3a9a3a'; tctx.setLineDash([6, 4]); tctx.lineWidth = 1.5;
    tctx.beginPath(); tctx.moveTo(X(line.x0), Y(line.y0)); tctx.lineTo(X(line.x1), Y(line.y1)); tctx.stroke();
    tctx.setLineDash([]);
  }
  tctx.fillStyle = '#1f4d8e'; tctx.beginPath(); tctx.arc(X(tx), Y(ty), 5, 0, 2 * Math.PI); tctx.fill();

  function drawGrid() {  // the grid, 5, 10 or 50 mm, on a clean lower canvas
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    const step = view.span > 200 ? 50 : view.span > 60 ? 10 : 5;
    ctx.strokeStyle = '#e2ded3'; ctx.lineWidth = 1; ctx.beginPath();
    for (let g = Math.floor((view.cx - view.span) / step) * step; g < view.cx + view.span; g += step) { ctx.moveTo(X(g), 0); ctx.lineTo(X(g), canvas.height); }
    for (let g = Math.floor((view.cy - view.span) / step) * step; g < view.cy + view.span; g += step) { ctx.moveTo(0, Y(g)); ctx.lineTo(canvas.width, Y(g)); }
    ctx.stroke();
    ctx.fillStyle = '#777'; ctx.font = '11px system-ui';
    ctx.fillText(`${step} mm grid`, 6, canvas.height - 6);
  }
}
let lastAxes = '', axesAt = 0;
function drawAxes(st, now) {
  const key = JSON.stringify(st.axes);
  if (key === lastAxes || (now - axesAt < 100 && st.running)) return;  // figures at 10 Hz: readable, cheap
  lastAxes = key;
  axesAt = now;
  ['x', 'y', 'z'].forEach((name, i) => {
    const a = st.axes[i];
    const row = $(`axis-${name}`);
    row.querySelector('.steps').textContent = a.steps;
    row.querySelector('.mm').textContent = a.mm.toFixed(2);
    row.querySelector('.count').textContent = a.count;
    row.querySelector('.lost').textContent = a.lost;
  });
  const z = st.axes[2].mm;
  const range = Math.max(2, Math.abs(z) * 1.25);
  $('zbar').style.height = `${Math.min(100, Math.abs(z) / range * 100)}%`;
  $('zmm').textContent = `Z ${z.toFixed(2)} mm`;
}

// ---- running: the pacer is the board's; the page gives each frame a slice of host time --------
let speed = 1;
let lastStatus = 0, runSince = performance.now(), tSince = 0;
function status(st, now) {
  if (now - lastStatus < 250) return;
  const ratio = (st.t - tSince) / CLOCK_HZ / ((now - runSince) / 1000);
  runSince = now; tSince = st.t; lastStatus = now;
  const s = $('status');
  s.dataset.ratio = ratio.toFixed(2);
  s.textContent = `${st.running ? 'running' : 'stopped' + (st.stop ? ` (${st.stop})` : '')} · ${(st.ms / 1000).toFixed(3)} s · ` +
    `${st.running ? ratio.toFixed(ratio < 10 ? 2 : 0) + '× real time' : ''} · PC ${st.pc.toString(16).toUpperCase().padStart(4, '0')}H`;
  $('run').textContent = st.running ? 'Pause' : 'Run';
}
// The log keeps its last 200 lines and is written to the page at most four times a second (a
// table at its end stop says so at every step).
const logLines = [];
let logDirty = false, logAt = 0;
function log(lines) {
  if (lines.length) {
    logLines.push(...lines);
    if (logLines.length > 200) logLines.splice(0, logLines.length - 200);
    logDirty = true;
  }
  const now = performance.now();
  if (!logDirty || now - logAt < 250) return;
  const l = $('log');
  l.textContent = logLines.join('\n') + '\n';
  l.scrollTop = l.scrollHeight;
  logDirty = false;
  logAt = now;
}
function frame(now) {
  board.frame(FRAME_BUDGET_S);
  const st = board.state();
  $('status').dataset.t = st.t;  // machine time in T-states (tests wait on it)
  window.alp85.frames++;
  drawDisplay();
  drawTable(st);
  drawAxes(st, now);
  status(st, now);
  log(board.takeLog());
  requestAnimationFrame(frame);
}

$('run').addEventListener('click', () => { if (board.running()) board.pause(); else { board.start(); board.setSpeed(speed); } });
$('reset').addEventListener('click', () => { board.key('RESET', true); board.key('RESET', false); resetPath(); board.clearPath(); });
for (const r of document.querySelectorAll('input[name=speed]'))
  r.addEventListener('change', () => { speed = Number(r.value); board.setSpeed(speed); });
function boot(name) {
  const err = board.boot(name);
  resetPath();
  log([err ? `firmware ${name}: ${err}` : `firmware ${name}: loaded, RESET`]);
  board.setSpeed(speed);
}
$('firmware').addEventListener('change', (e) => boot(e.target.value));

// ---- snapshots: the file alp85 save writes, downloaded and picked ------------------------------
$('save').addEventListener('click', () => {
  const bytes = board.save();
  if (typeof bytes === 'string') { log([`save: ${bytes}`]); return; }
  const a = document.createElement('a');
  a.href = URL.createObjectURL(new Blob([bytes], { type: 'application/octet-stream' }));
  a.download = 'alp85.alp85snap';
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  log([`saved a snapshot (${bytes.length} bytes)`]);
});
$('open').addEventListener('change', async (e) => {
  const f = e.target.files[0];
  if (!f) return;
  const err = board.restore(new Uint8Array(await f.arrayBuffer()));
  resetPath();
  board.setSpeed(speed);
  log([err ? `restore ${f.name}: ${err}` : `restored ${f.name}`]);
  e.target.value = '';
});

// ---- the editor: asm85's diagnostics at their lines --------------------------------------------
const source = $('source');
source.value = mod.FS.readFile('/src/demo/hello85.asm', { encoding: 'utf8' });
let marks = new Map();
function drawGutter() {
  const n = source.value.split('\n').length;
  const out = [];
  for (let i = 1; i <= n; i++) {
    const m = marks.get(i);
    out.push(m ? `<span class="${m.severity}" title="${m.message.replace(/"/g, '&quot;')}">${i}</span>` : `${i}`);
  }
  $('gutter').innerHTML = out.join('\n');
  source.style.height = `${n * 18 + 12}px`;
}
source.addEventListener('input', () => { marks = new Map(); drawGutter(); });
drawGutter();
function selectAt(line, col) {
  const lines = source.value.split('\n');
  let pos = 0;
  for (let i = 0; i < line - 1 && i < lines.length; i++) pos += lines[i].length + 1;
  pos += Math.max(0, col - 1);
  source.focus();
  source.setSelectionRange(pos, pos + 1);
}
$('assemble').addEventListener('click', () => {
  const r = board.assemble(source.value);
  const list = $('diagnostics');
  list.textContent = '';
  marks = new Map();
  for (const d of r.diagnostics) {
    const li = document.createElement('li');
    li.className = d.severity;
    li.dataset.line = d.line;
    li.dataset.col = d.col;
    const where = d.file.endsWith('program.asm') ? '' : `${d.file.replace(/^\/src\//, '')}:`;
    li.textContent = `${where}${d.line}:${d.col}: ${d.severity}: ${d.message}`;
    if (d.line) li.addEventListener('click', () => selectAt(d.line, d.col));
    list.appendChild(li);
    if (d.line && d.file.endsWith('program.asm') && !marks.has(d.line)) marks.set(d.line, d);
  }
  drawGutter();
  const li = document.createElement('li');
  li.className = r.ok ? 'ok' : 'error';
  li.id = 'assembly-result';
  li.textContent = r.ok
    ? (r.load ? `not loaded: ${r.load}` : `assembled and loaded: ${r.bytes} bytes, ${r.lowest.toString(16).toUpperCase()}H–${r.highest.toString(16).toUpperCase()}H`)
    : `${r.diagnostics.filter((d) => d.severity === 'error').length} error(s); nothing loaded`;
  list.appendChild(li);
});

// ---- G-code for the master program --------------------------------------------------------------
$('gcode-load').addEventListener('click', () => {
  if ($('firmware').value !== 'master') { $('firmware').value = 'master'; boot('master'); }
  const err = board.gcode($('gcode-text').value);
  $('gcode-msg').textContent = err ? `G-code: ${err}` : 'path table loaded at 3DD0H: R 7 3000 EXEC, then 1 and EXEC';
});

// ---- Appendix C as a guided demo ----------------------------------------------------------------
let demoAt = -1;
function showDemo() {
  const ol = $('demo-steps');
  ol.textContent = '';
  WALKTHROUGH.forEach((s, i) => {
    const li = document.createElement('li');
    li.className = i < demoAt ? 'done' : i === demoAt ? 'current' : '';
    li.innerHTML = `${s.say} <span class="keys"></span>`;
    li.querySelector('.keys').append(...s.keys.map((k) => { const e = document.createElement('kbd'); e.textContent = k; return e; }));
    ol.appendChild(li);
  });
  for (const b of keyButtons.values()) b.classList.remove('hint-on');
  if (demoAt >= 0 && demoAt < WALKTHROUGH.length) for (const k of WALKTHROUGH[demoAt].keys) keyButtons.get(k)?.classList.add('hint-on');
  $('demo-next').disabled = demoAt < 0 || demoAt >= WALKTHROUGH.length;
}
const until = (pred, ms) => new Promise((ok) => {
  const t0 = performance.now();
  const poll = () => (pred() || performance.now() - t0 > ms ? ok(pred()) : requestAnimationFrame(poll));
  poll();
});
async function pressKeys(keys) {
  for (const k of keys) {
    board.key(k, true);
    board.key(k, false);
    const t = board.state().t;
    await until(() => board.state().t > t + 0.06 * CLOCK_HZ, 5000);  // its hold and the gap (30 + 30 ms)
  }
}
$('demo-start').addEventListener('click', () => {
  $('firmware').value = 'thesis-fixed';
  boot('thesis-fixed');
  demoAt = 0;
  showDemo();
});
$('demo-next').addEventListener('click', async () => {
  const s = WALKTHROUGH[demoAt];
  $('demo-next').disabled = true;
  await pressKeys(s.keys);
  if (s.wait) await until(() => $('display').dataset.text.trimEnd() === s.wait, 20000);
  demoAt++;
  showDemo();
});
showDemo();

boot('thesis-fixed');
window.alp85 = { board, ready: true, frames: 0 };
requestAnimationFrame(frame);
