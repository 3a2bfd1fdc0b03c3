// The page: draws what the board (alp85.wasm, web/binding.cpp) shows and hands it the user's
// keys, files and text. Every decision about the machine is the board's; this file only draws.
import createAlp85 from './alp85.js';
import { WALKTHROUGH } from './walkthrough.js';

const $ = (id) => document.getElementById(id);
const CLOCK_HZ = 3072000;
// Host time the machine may take in one frame (60 fps leaves 16.7 ms): paced, far more than it
// needs; as fast as possible, most of the frame, the rest left for drawing it.
const FRAME_BUDGET_S = 0.010, UNPACED_BUDGET_S = 0.014;

const mod = await createAlp85();
// The board the URL asks for (?board=sdk85; the default board without one, or for a name there is
// none of); the selector loads the page again with another.
const board = new mod.Board(new URLSearchParams(location.search).get('board') ?? '');
for (const [name, title] of mod.boards()) {
  const o = document.createElement('option');
  o.value = name;
  o.textContent = title;
  o.selected = name === board.name();
  $('board-choice').appendChild(o);
}
$('board-choice').addEventListener('change', (e) => { location.search = `?board=${encodeURIComponent(e.target.value)}`; });
document.title = `ALP85 — ${board.title()}`;
// What the page shows of a board is what its description has: the machine tool's views only with
// the tool, the firmware choice for the board whose monitor is built in, Load ROM... for the rest.
for (const id of ['tool', 'demo', 'gcode']) $(id).hidden = !board.hasTool();
// The editor's demo and its INCLUDE are the built-in monitor's (the ALP 85's).
for (const id of ['firmware-choice', 'editor']) $(id).hidden = board.userRom();
$('rom-choice').hidden = !board.userRom();

// ---- the display: the board's seven-segment digits (a = bit 0 ... g = bit 6, dp = bit 7) -------
const SEGMENTS = [  // polygons in a 44 x 72 box, a b c d e f g, then the dot
  '8,4 36,4 32,9 12,9', '37,6 37,34 33,32 33,10', '37,38 37,66 33,62 33,40', '8,68 36,68 32,63 12,63',
  '7,38 7,66 11,62 11,40', '7,6 7,34 11,32 11,10', '9,36 13,33 31,33 35,36 31,39 13,39',
];
const digits = [];
const DIGITS = board.digits();
for (let i = 0; i < DIGITS; i++) {
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
// What the board shows, copied each frame from its snapshot (web/binding.cpp: the same numbers).
const SNAP = { t: 0, pc: 1, running: 2, stops: 3, displayChanges: 4, digits: 5, axes: 13, pathSize: 25, ideal: 26, log: 31, halted: 32 };
const S = new Float64Array(33);
let shownChanges = -1;
const shown = new Array(DIGITS).fill(-1);
function drawDisplay() {  // only when the segments changed
  if (S[SNAP.displayChanges] === shownChanges) return;
  shownChanges = S[SNAP.displayChanges];
  for (let i = 0; i < DIGITS; i++) {
    const byte = S[SNAP.digits + i];
    if (byte === shown[i]) continue;
    const was = shown[i] < 0 ? ~byte : shown[i];
    digits[i].forEach((seg, bit) => { if (((byte ^ was) >> bit & 1) === 1) seg.classList.toggle('on', (byte >> bit & 1) === 1); });
    shown[i] = byte;
  }
  const text = board.displayText();
  const d = $('display');
  if (d.dataset.text !== text) { d.dataset.text = text; d.setAttribute('aria-label', `display: ${text}`); }
}

// ---- the keypad, laid out and captioned as the window's (the board's description); its PC keys -
const keyButtons = new Map();
const pad = board.keypad();
$('keypad').style.gridTemplateColumns = `repeat(${Math.max(...pad.map((k) => k.col)) + 1}, 62px)`;  // as the description places them
for (const k of pad) {
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

// The slow parts (the status line, the axes' figures, the path's canvas, the log) are drawn
// together, at most 4 times a second. Each frame that changes the picture costs every Chromium
// process again (without a GPU the compositing is the CPU's), so their changes share a frame
// rather than take one each (docs/web.md: the page at real time).
const SLOW_MS = 250;
let slowAt = -Infinity, slowDrawn = false;
const slowDue = (now) => now - slowAt >= SLOW_MS;

// ---- the machine tool: X-Y table (ideal line, toolpath, tool), Z gauge, the axes' figures -------
// Layers, one over the other: below, a canvas with the grid and the toolpath, drawn once and
// extended 4 times a second (redrawn whole only when the view moves: a changed canvas is sent to
// the compositor whole); over it the path's newest part, from the canvas's last point to the tool,
// a straight stroke (the path of at most a quarter of a second) that the compositor turns and stretches; then
// the ideal line's canvas, drawn when it or the view changes; on top, the tool, an element the
// compositor moves. The canvases are as many pixels as they show (no scaling when composited).
const canvas = $('table');
const ctx = canvas.getContext('2d');
const top = $('table-top');
const tctx = top.getContext('2d');
const toolDot = $('tool-dot');
let path = new Float64Array(1 << 16), pathLen = 0;  // x, y pairs in table mm
// The tool is drawn at whole CSS pixels: a move smaller than a pixel changes nothing to draw.
const chord = $('table-chord');
let bounds = null, view = null, drawnPoints = 0, canvasPoints = 0, lineKey = '', toolPx = [NaN, NaN], cssScale = 1;
new ResizeObserver(() => {
  const dpr = window.devicePixelRatio || 1;
  const w = Math.round(canvas.clientWidth * dpr), h = Math.round(w * 3 / 4);
  if (w === canvas.width && h === canvas.height) return;
  for (const c of [canvas, top]) { c.width = w; c.height = h; }
  cssScale = 1 / dpr;
  view = null;
  wantDraw();
}).observe(canvas);
function grow(x, y) {
  if (!bounds) bounds = { x0: x, x1: x, y0: y, y1: y };
  if (x < bounds.x0) bounds.x0 = x; else if (x > bounds.x1) bounds.x1 = x;
  if (y < bounds.y0) bounds.y0 = y; else if (y > bounds.y1) bounds.y1 = y;
}
function resetPath() { pathLen = 0; bounds = null; view = null; drawnPoints = 0; lineKey = ''; toolPx = [NaN, NaN]; }
// The path's points not yet on the canvas are drawn there with the other slow parts.
function flushRecent() {
  if (drawnPoints > canvasPoints + 1) {
    ctx.strokeStyle = '#c0392b'; ctx.lineWidth = 2; ctx.lineJoin = 'round'; ctx.beginPath();
    const from = Math.max(0, canvasPoints - 1);
    ctx.moveTo(X(path[2 * from]), Y(path[2 * from + 1]));
    for (let i = from + 1; i < drawnPoints; i++) ctx.lineTo(X(path[2 * i]), Y(path[2 * i + 1]));
    ctx.stroke();
  }
  canvasPoints = drawnPoints;
  slowDrawn = true;
}
// The stroke from the canvas's last point to the tool (whole CSS pixels, as the tool).
let chordShown = '';
function drawChord(px, py) {
  let t = 'scaleX(0)';
  if (canvasPoints > 0) {
    const ax = Math.round(X(path[2 * canvasPoints - 2]) * cssScale), ay = Math.round(Y(path[2 * canvasPoints - 1]) * cssScale);
    const len = Math.hypot(px - ax, py - ay);
    if (len >= 1) t = `translate(${ax}px, ${ay}px) rotate(${Math.atan2(py - ay, px - ax).toFixed(3)}rad) scaleX(${len.toFixed(1)})`;
  }
  if (t !== chordShown) chord.style.transform = chordShown = t;
}
// Whether the table's picture would change: the tool a pixel away, the line moved, the path cut
// back, or grown while the tool stands (its last points, closer than a pixel, drawn within 0.25 s).
function tableChanged(now) {
  if (!view || S[SNAP.pathSize] < pathLen / 2) return true;
  if (Math.round(X(S[SNAP.axes + 1]) * cssScale) !== toolPx[0] || Math.round(Y(S[SNAP.axes + 5]) * cssScale) !== toolPx[1]) return true;
  if ((S[SNAP.ideal] === 1) !== (lineKey !== '-') || (S[SNAP.ideal] === 1 && lineKey !== lineText())) return true;
  return S[SNAP.pathSize] !== canvasPoints && slowDue(now);
}
function drawTable(now) {
  if (!tableChanged(now)) return;
  const n = S[SNAP.pathSize];
  if (n < pathLen / 2) resetPath();
  if (n > pathLen / 2) {
    const more = board.pathSince(pathLen / 2);
    if (pathLen + more.length > path.length) {
      const bigger = new Float64Array(Math.max(path.length * 2, pathLen + more.length));
      bigger.set(path.subarray(0, pathLen));
      path = bigger;
    }
    path.set(more, pathLen);
    for (let i = 0; i < more.length; i += 2) grow(more[i], more[i + 1]);
    pathLen += more.length;
  }
  const hasLine = S[SNAP.ideal] === 1;
  const tx = S[SNAP.axes + 1], ty = S[SNAP.axes + 5];
  grow(0, 0); grow(tx, ty);
  if (hasLine) { grow(S[SNAP.ideal + 1], S[SNAP.ideal + 2]); grow(S[SNAP.ideal + 3], S[SNAP.ideal + 4]); }
  const b = bounds;
  const span = Math.max(b.x1 - b.x0, (b.y1 - b.y0) * canvas.width / canvas.height, 20) * 1.15;
  // The view's span is a 1-2-5 step at or above the picture's, centred on it: a growing path moves
  // the view now and then (when it leaves it), not every frame.
  const fits = view && span <= view.span && b.x0 >= view.cx - view.span / 2 && b.x1 <= view.cx + view.span / 2 &&
    b.y0 >= view.cy - view.span * canvas.height / canvas.width / 2 && b.y1 <= view.cy + view.span * canvas.height / canvas.width / 2;
  if (!fits) {
    const decade = 10 ** Math.floor(Math.log10(span));
    view = { span: [1, 2, 5, 10].map((m) => m * decade).find((v) => v >= span), cx: (b.x0 + b.x1) / 2, cy: (b.y0 + b.y1) / 2 };
    view.scale = canvas.width / view.span;
    drawnPoints = canvasPoints = 0;
    lineKey = '';
    drawGrid();
  }
  drawnPoints = pathLen / 2;
  if (drawnPoints > canvasPoints && (canvasPoints === 0 || slowDue(now))) flushRecent();
  // the ideal line over the toolpath, so that both show where they coincide
  const key = hasLine ? lineText() : '-';
  if (key !== lineKey) {
    lineKey = key;
    tctx.clearRect(0, 0, top.width, top.height);
    if (hasLine) {
      tctx.strokeStyle = '#3a9a3a'; tctx.setLineDash([6, 4]); tctx.lineWidth = 1.5; tctx.beginPath();
      tctx.moveTo(X(S[SNAP.ideal + 1]), Y(S[SNAP.ideal + 2])); tctx.lineTo(X(S[SNAP.ideal + 3]), Y(S[SNAP.ideal + 4])); tctx.stroke();
    }
  }
  const px = Math.round(X(tx) * cssScale), py = Math.round(Y(ty) * cssScale);
  if (px !== toolPx[0] || py !== toolPx[1]) {
    toolPx = [px, py];
    toolDot.style.transform = `translate(${px}px, ${py}px)`;
  }
  drawChord(px, py);
}
function lineText() { return `${S[SNAP.ideal + 1]} ${S[SNAP.ideal + 2]} ${S[SNAP.ideal + 3]} ${S[SNAP.ideal + 4]}`; }
function X(x) { return canvas.width / 2 + (x - view.cx) * view.scale; }
function Y(y) { return canvas.height / 2 - (y - view.cy) * view.scale; }
function drawGrid() {  // the grid, 5, 10 or 50 mm, on a clean lower canvas
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  const step = view.span > 200 ? 50 : view.span > 60 ? 10 : 5;
  ctx.strokeStyle = '#e2ded3'; ctx.lineWidth = 1; ctx.beginPath();
  for (let g = Math.floor((view.cx - view.span) / step) * step; g < view.cx + view.span; g += step) { ctx.moveTo(X(g), 0); ctx.lineTo(X(g), canvas.height); }
  for (let g = Math.floor((view.cy - view.span) / step) * step; g < view.cy + view.span; g += step) { ctx.moveTo(0, Y(g)); ctx.lineTo(canvas.width, Y(g)); }
  ctx.stroke();
  drawNumbers(step);
}
// The grid lines' values in mm, X along the bottom edge and Y along the left, as elements over
// the canvas (written when the view moves): every grid line's, or every second or fifth one's
// where they would stand closer than 48 CSS pixels.
function drawNumbers(step) {
  const every = [1, 2, 5, 10].map((k) => k * step).find((s) => s * view.scale * cssScale >= 48) ?? 10 * step;
  const numbers = (box, lo, hi, at) => {
    const spans = [];
    for (let g = Math.ceil(lo / every) * every; g <= hi; g += every) {
      const e = document.createElement('span');
      e.textContent = `${Number(g.toFixed(3))}`;
      e.dataset.mm = g;
      at(e, g);
      spans.push(e);
    }
    box.replaceChildren(...spans);
  };
  const w = canvas.width, h = canvas.height, x0 = view.cx - w / 2 / view.scale, y0 = view.cy - h / 2 / view.scale;
  // Leave the corner where both edges meet to the Y numbers (an X number there would cover one),
  // and no number so near the far edges that it would be cut.
  const px = 1 / view.scale / cssScale;  // mm in a CSS pixel
  numbers($('table-xnums'), x0 + 30 * px, x0 + w / view.scale - 14 * px, (e, g) => { e.style.left = `${X(g) * cssScale}px`; });
  numbers($('table-ynums'), y0 + 20 * px, y0 + h / view.scale - 8 * px, (e, g) => { e.style.top = `${Y(g) * cssScale}px`; });
}
// The axes' figures, with the other slow parts while they change: a cell is written only when its
// figure changed; the Z gauge is scaled by the compositor.
const cells = ['x', 'y', 'z'].map((name) => ['.steps', '.mm', '.count', '.lost'].map((c) => $(`axis-${name}`).querySelector(c)));
const shownAxes = new Float64Array(12).fill(NaN);
let shownZ = NaN;
function axesChanged(now) {
  if (!slowDue(now)) return false;
  for (let i = 0; i < 12; i++) if (S[SNAP.axes + i] !== shownAxes[i]) return true;
  return false;
}
function drawAxes(now) {
  if (!axesChanged(now)) return;
  slowDrawn = true;
  for (let i = 0; i < 12; i++) {
    const v = S[SNAP.axes + i];
    if (v === shownAxes[i]) continue;
    shownAxes[i] = v;
    cells[i >> 2][i & 3].textContent = (i & 3) === 1 ? v.toFixed(2) : v;
  }
  const z = S[SNAP.axes + 9];
  if (z === shownZ) return;
  shownZ = z;
  const range = Math.max(2, Math.abs(z) * 1.25);
  $('zbar').style.transform = `scaleY(${Math.min(1, Math.abs(z) / range).toFixed(4)})`;
  $('zmm').textContent = `Z ${z.toFixed(2)} mm`;
}

// ---- running: the pacer is the board's; the page gives each frame a slice of host time --------
let speed = 1;
let runSince = performance.now(), tSince = 0, shownRun = '';
let statusShown = '';
function statusDue(now) {  // 4 times a second while running, and when the run starts or stops
  return slowDue(now) && (S[SNAP.running] === 1 || statusShown !== `${S[SNAP.running]} ${S[SNAP.stops]}`);
}
function status(now) {
  if (!statusDue(now)) return;
  statusShown = `${S[SNAP.running]} ${S[SNAP.stops]}`;
  const t = S[SNAP.t], running = S[SNAP.running] === 1;
  const ratio = (t - tSince) / CLOCK_HZ / ((now - runSince) / 1000);
  runSince = now; tSince = t; slowDrawn = true;
  const stop = running ? '' : board.stopText();
  // After a HLT the board's clock runs on (RESET and interrupts still answer), but the CPU waits.
  const state = running ? (S[SNAP.halted] === 1 ? 'halted' : 'running') : 'stopped' + (stop ? ` (${stop})` : '');
  $('status').textContent = `${state} · ${(t / CLOCK_HZ).toFixed(3)} s · ` +
    `${running ? ratio.toFixed(ratio < 10 ? 2 : 0) + '× real time' : ''} · PC ${S[SNAP.pc].toString(16).toUpperCase().padStart(4, '0')}H`;
  const run = running ? 'Pause' : 'Run';
  if (run !== shownRun) $('run').textContent = shownRun = run;
}
// The log keeps its last 200 lines and is written to the page at most four times a second (a
// table at its end stop says so at every step).
const logLines = [];
let logDirty = false;
function log(lines) {
  if (!lines.length) return;
  logLines.push(...lines);
  if (logLines.length > 200) logLines.splice(0, logLines.length - 200);
  logDirty = true;
  wantDraw();
}
function drawLog(now) {
  if (!logDirty || !slowDue(now)) return;
  const l = $('log');
  l.textContent = logLines.join('\n') + '\n';
  l.scrollTop = l.scrollHeight;
  logDirty = false;
  slowDrawn = true;
}

// ---- the loop: the board runs in ticks, 60 a second against the host clock (as fast as possible:
// one after another); a frame is drawn only when a tick changed what the page shows, so that a
// board standing still costs a tick and nothing else. window.alp85.t is the machine's time and
// .at the host's instant it was read (tests and the figures wait on them).
const TICK_MS = 1000 / 60;
const next = new MessageChannel();
next.port1.onmessage = tick;
let tickDue = performance.now(), drawPending = false, wantedAt = 0;
function tick() {
  const now = performance.now();
  board.frame(speed === 0 ? UNPACED_BUDGET_S : FRAME_BUDGET_S);
  S.set(board.snapshot());
  const a = window.alp85;
  a.t = S[SNAP.t];
  a.at = performance.now();
  a.ticks++;
  if (S[SNAP.log] > 0) log(board.takeLog());
  if (S[SNAP.displayChanges] !== shownChanges || tableChanged(now) || axesChanged(now) || statusDue(now) || (logDirty && slowDue(now)))
    wantDraw();
  if (speed === 0) {
    next.port2.postMessage(0);
    return;
  }
  tickDue += TICK_MS;
  if (tickDue < a.at - 100) tickDue = a.at;  // far behind (a busy host, a hidden tab): no burst of ticks
  setTimeout(tick, Math.max(0, tickDue - a.at));
}
function wantDraw() {
  if (drawPending) return;
  drawPending = true;
  wantedAt = performance.now();
  requestAnimationFrame(draw);
}
// A frame is late when it is drawn more than two display frames after the change it shows.
function draw(now) {
  drawPending = false;
  window.alp85.frames++;
  if (now - wantedAt > 2 * TICK_MS) window.alp85.late++;
  drawDisplay();
  drawTable(now);
  drawAxes(now);
  status(now);
  drawLog(now);
  if (slowDrawn) { slowAt = now; slowDrawn = false; }
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
// Load ROM...: the user's file, checked by the board's ROM loader (as alp85's --rom); its refusal
// is shown beside the button, and the board then runs what it ran before.
function romLoaded(what, err) {
  $('rom-msg').textContent = err ? `ROM ${what}: ${err}` : `ROM ${what}: loaded, RESET`;
  $('rom-msg').className = err ? 'error' : '';
  log([$('rom-msg').textContent]);
  resetPath();
  board.setSpeed(speed);
}
$('rom').addEventListener('change', async (e) => {
  const f = e.target.files[0];
  if (!f) return;
  romLoaded(f.name, board.loadRom(f.name, new Uint8Array(await f.arrayBuffer())));
  e.target.value = '';
});

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
    const t = window.alp85.t;
    await until(() => window.alp85.t > t + 0.06 * CLOCK_HZ, 5000);  // its hold and the gap (30 + 30 ms)
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

if (board.userRom()) romLoaded('the SDK-85 test program (firmware/sdk85/sdk85test.asm)', board.bootTestRom());
else boot('thesis-fixed');
window.alp85 = { board, ready: true, ticks: 0, frames: 0, late: 0, t: 0, at: 0, pathPoints: () => pathLen / 2 };
tick();
