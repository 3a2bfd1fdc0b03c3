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
function drawTable(st) {
  const n = board.pathSize();
  if (n < path.length / 2) path.length = 0;
  if (n > path.length / 2) path.push(...board.pathSince(path.length / 2));
  const line = board.ideal();
  const tx = st.axes[0].mm, ty = st.axes[1].mm;
  let x0 = Math.min(0, tx), x1 = Math.max(0, tx), y0 = Math.min(0, ty), y1 = Math.max(0, ty);
  const grow = (x, y) => { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); };
  for (let i = 0; i < path.length; i += 2) grow(path[i], path[i + 1]);
  if (line) { grow(line.x0, line.y0); grow(line.x1, line.y1); }
  const span = Math.max(x1 - x0, (y1 - y0) * canvas.width / canvas.height, 20) * 1.15;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const scale = canvas.width / span;
  const X = (x) => canvas.width / 2 + (x - cx) * scale;
  const Y = (y) => canvas.height / 2 - (y - cy) * scale;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  // millimetre grid, every 5 mm
  ctx.strokeStyle = '#e2ded3'; ctx.lineWidth = 1; ctx.beginPath();
  const step = span > 200 ? 50 : span > 60 ? 10 : 5;
  for (let g = Math.floor((cx - span) / step) * step; g < cx + span; g += step) { ctx.moveTo(X(g), 0); ctx.lineTo(X(g), canvas.height); }
  for (let g = Math.floor((cy - span) / step) * step; g < cy + span; g += step) { ctx.moveTo(0, Y(g)); ctx.lineTo(canvas.width, Y(g)); }
  ctx.stroke();
  ctx.fillStyle = '#777'; ctx.font = '11px system-ui';
  ctx.fillText(`${step} mm grid`, 6, canvas.height - 6);
  if (path.length >= 4) {
    ctx.strokeStyle = '#c0392b'; ctx.lineWidth = 2; ctx.beginPath();
    ctx.moveTo(X(path[0]), Y(path[1]));
    for (let i = 2; i < path.length; i += 2) ctx.lineTo(X(path[i]), Y(path[i + 1]));
    ctx.stroke();
  }
  // the ideal line over the toolpath, so that both show where they coincide
  if (line) {
    ctx.strokeStyle = '#3a9a3a'; ctx.setLineDash([6, 4]); ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.moveTo(X(line.x0), Y(line.y0)); ctx.lineTo(X(line.x1), Y(line.y1)); ctx.stroke();
    ctx.setLineDash([]);
  }
  ctx.fillStyle = '#1f4d8e'; ctx.beginPath(); ctx.arc(X(tx), Y(ty), 5, 0, 2 * Math.PI); ctx.fill();
}
function drawAxes(st) {
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
function log(lines) {
  if (!lines.length) return;
  const l = $('log');
  l.textContent += lines.join('\n') + '\n';
  l.scrollTop = l.scrollHeight;
}
function frame(now) {
  board.frame(FRAME_BUDGET_S);
  const st = board.state();
  $('status').dataset.t = st.t;  // machine time in T-states (tests wait on it)
  window.alp85.frames++;
  drawDisplay();
  drawTable(st);
  drawAxes(st);
  status(st, now);
  log(board.takeLog());
  requestAnimationFrame(frame);
}

$('run').addEventListener('click', () => { if (board.running()) board.pause(); else { board.start(); board.setSpeed(speed); } });
$('reset').addEventListener('click', () => { board.key('RESET', true); board.key('RESET', false); path.length = 0; board.clearPath(); });
for (const r of document.querySelectorAll('input[name=speed]'))
  r.addEventListener('change', () => { speed = Number(r.value); board.setSpeed(speed); });
function boot(name) {
  const err = board.boot(name);
  path.length = 0;
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
  path.length = 0;
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
  $('gcode-msg').textContent = err ? `G-code: ${err}` : 'path table loaded at 3D00H: R 7 3000 EXEC, then 1 and EXEC';
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
