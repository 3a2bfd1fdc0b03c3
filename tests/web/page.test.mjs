// The web page in a real browser: Debian's chromium, headless, driven by puppeteer-core against
// build/web served on 127.0.0.1 (python3 -m http.server, as scripts/web.sh serves it).
//   node tests/web/page.test.mjs            the acceptance test (CTest web:page)
//   node tests/web/page.test.mjs --bench    the figures of docs/web.md (load time, speed, CPU)
// Environment: ALP85 (the native alp85), ALP85_WEB_DIR (the built site), ALP85_SDK85_ROM (the SDK-85
// test program's .hex, for Load ROM), ALP85_DOC_IMAGES (a
// folder: the page's screenshot goes there as web.png).
import { spawn, execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import assert from 'node:assert/strict';

const here = dirname(fileURLToPath(import.meta.url));
const CHROMIUM = process.env.ALP85_CHROMIUM || '/usr/bin/chromium';
const site = process.env.ALP85_WEB_DIR;
const alp85 = process.env.ALP85;
const bench = process.argv.includes('--bench');
var CLOCK_HZ = 3072000;  // var: read by functions the top-level run reaches first

let puppeteer;
try {
  puppeteer = (await import('puppeteer-core')).default;
} catch {
  fail('puppeteer-core is not installed in tests/web: run scripts/setup.sh --tests');
}
if (!existsSync(CHROMIUM)) fail(`no browser at ${CHROMIUM}: run scripts/setup.sh --tests (it installs chromium)`);
if (!site || !existsSync(join(site, 'alp85.wasm'))) fail(`no built page in ${site}: run scripts/web.sh --build`);
if (!alp85 || !existsSync(alp85)) fail('ALP85 must name the native alp85');

function fail(msg) {
  console.error(`web:page: ${msg}`);
  process.exit(1);
}

// ---- the server and the browser -----------------------------------------------------------------
const server = spawn('python3', ['-u', '-m', 'http.server', '0', '--bind', '127.0.0.1', '--directory', site],
  { stdio: ['ignore', 'pipe', 'pipe'] });
const port = await new Promise((ok, no) => {
  let text = '';
  server.stdout.on('data', (d) => {
    text += d;
    const m = text.match(/port (\d+)/);
    if (m) ok(Number(m[1]));
  });
  server.on('exit', (c) => no(new Error(`http.server exited (${c})`)));
  setTimeout(() => no(new Error('http.server did not start')), 10000);
});
const profile = mkdtempSync(join(tmpdir(), 'alp85-chromium-'));
const browser = await puppeteer.launch({
  executablePath: CHROMIUM,
  headless: true,
  userDataDir: profile,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
    '--disable-component-update', '--disable-sync'],
});
let status = 0;
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 1000 });
  // Offline: every request the page makes goes to the server on 127.0.0.1.
  const foreign = [];
  page.on('request', (r) => { if (!r.url().startsWith(`http://127.0.0.1:${port}/`) && !r.url().startsWith('blob:')) foreign.push(r.url()); });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  // Every request answered (a missing /favicon.ico is a 404 and a console error on every load).
  page.on('response', (r) => { if (r.status() >= 400) errors.push(`${r.status()} ${r.url()}`); });
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  const t0 = Date.now();
  await page.goto(`http://127.0.0.1:${port}/`);
  await page.waitForFunction(() => window.alp85?.ready, { timeout: 30000 });
  const loadMs = Date.now() - t0;
  console.log(`page ready in ${loadMs} ms`);
  if (bench) await figures(page, loadMs);
  else await acceptance(page);
  assert.deepEqual(errors, [], 'the page threw');
  assert.deepEqual(foreign, [], 'the page asked for something outside 127.0.0.1');
  console.log('web:page: all checks passed');
} catch (e) {
  console.error(`web:page: FAILED: ${e.stack || e}`);
  status = 1;
} finally {
  await browser.close();
  server.kill();
  rmSync(profile, { recursive: true, force: true });
}
process.exit(status);

// ---- helpers: the page's DOM -----------------------------------------------------------------------
function display(page) { return page.$eval('#display', (d) => d.dataset.text); }
async function waitDisplay(page, text, ms = 20000) {
  try {
    // blank digits on the right are spaces in the text, as `wait display` ignores them
    await page.waitForFunction((t) => document.querySelector('#display').dataset.text.trimEnd() === t, { timeout: ms, polling: 'raf' }, text);
  } catch {
    throw new Error(`the display did not read "${text}" (it reads "${await display(page)}")`);
  }
}
// Machine time (T-states) as the page last drew it, to let each key's hold and gap pass.
function machineT(page) { return page.evaluate(() => window.alp85.t); }
async function click(page, key) {
  await page.click(`#keypad button[data-key="${key}"]`);
  const t = await machineT(page);
  await page.waitForFunction((t0) => window.alp85.t > t0 + 0.07 * 3072000,
    { timeout: 20000, polling: 'raf' }, t);
}
async function type(page, keys) {
  for (const k of keys) await click(page, k);
}
async function axes(page) {
  return page.$$eval('#axes tbody tr', (rows) => rows.map((r) => ({
    steps: Number(r.querySelector('.steps').textContent),
    count: Number(r.querySelector('.count').textContent),
    lost: Number(r.querySelector('.lost').textContent),
  })));
}

// The axes' figures once they hold still: the page redraws them at most 10 times a second while
// it runs, so right after the display changes they may be one redraw behind.
async function settledAxes(page) {
  let last = await axes(page);
  for (let i = 0; i < 20; ++i) {
    await new Promise((r) => setTimeout(r, 250));
    const now = await axes(page);
    if (JSON.stringify(now) === JSON.stringify(last)) return now;
    last = now;
  }
  return last;
}

// The same session run by the native alp85 (`alp85 script`): its `print axes`.
// It saves bitti.snap into `dir`.
function nativeAxes(dir) {
  const out = execFileSync(alp85, ['script', '--out-dir', dir, join(here, 'walkthrough.alp')], { encoding: 'utf8' });
  const axes = {};
  for (const m of out.matchAll(/^\s+([XYZ])\s+(-?\d+) steps.*count\s+(-?\d+)\s+commanded\s+(-?\d+)\s+lost (-?\d+)/gm))
    axes[m[1]] = { steps: Number(m[4]), count: Number(m[3]), lost: Number(m[5]) };
  assert.equal(Object.keys(axes).length, 3, `alp85 script printed no axes:\n${out}`);
  return [axes.X, axes.Y, axes.Z];
}

// ---- the acceptance test ---------------------------------------------------------------------------
async function acceptance(page) {
  await page.click('input[name=speed][value="10"]');
  // Appendix C, the worked line of docs/thesis.md (scripts/thesis/line_q1_worked.alp): clicked on
  // the page's keys, the display read at each prompt.
  await type(page, ['RESET']);
  await waitDisplay(page, '-ALP 85-');
  await type(page, ['R', '7', '0', '8', '0', '0', 'EXEC']);
  await waitDisplay(page, '?.=----');
  await type(page, ['0', '0', '1', '2']);  // Z = 12 steps; the next prompt follows the fourth digit
  await waitDisplay(page, 'H1=----');
  const entries = [['0100', 'H1=', 'y1='], ['0050', 'y1=', 'H2='], ['0300', 'H2=', 'y2='], ['0200', 'y2=', 'H=']];
  for (const [digits, prompt, next] of entries) {
    await type(page, [...digits]);
    await waitDisplay(page, prompt + digits);
    await type(page, ['EXEC']);
    await waitDisplay(page, `${next}----`);
  }
  await type(page, [...'0750']);
  await waitDisplay(page, 'H=0750');
  await type(page, ['EXEC']);
  await waitDisplay(page, '  8itti', 30000);
  // The firmware ends with HLT after Bitti (firmware/thesis/thesis.asm, L35): the board's clock
  // runs on, the CPU waits, and the status says so.
  try {
    await page.waitForFunction(() => /^halted · /.test(document.querySelector('#status').textContent), { timeout: 5000 });
  } catch {
    throw new Error(`the status after the HLT reads "${await page.$eval('#status', (e) => e.textContent)}", not "halted · ..."`);
  }
  console.log(`status after HLT: ${await page.$eval('#status', (e) => e.textContent)}`);
  const seen = await settledAxes(page);
  // From the thesis line: (X2 - X1, Y2 - Y1) = (300 - 100, 200 - 50) steps of 0.05 mm, and Z's 12;
  // the transducers count what the table did, and nothing is lost at 750 mm/min.
  assert.deepEqual(seen, [{ steps: 200, count: 200, lost: 0 }, { steps: 150, count: 150, lost: 0 }, { steps: 12, count: 12, lost: 0 }],
    'the page\'s axes after Bitti');
  if (process.env.ALP85_DOC_IMAGES) {
    await page.screenshot({ path: join(process.env.ALP85_DOC_IMAGES, 'web.png') });
    console.log(`screenshot: ${join(process.env.ALP85_DOC_IMAGES, 'web.png')}`);
  }
  await tableView(page);
  await pageFurniture(page);
  const snapDir = mkdtempSync(join(tmpdir(), 'alp85-web-snap-'));
  try {
    assert.deepEqual(seen, nativeAxes(snapDir), 'the page against `alp85 script` on the same line');
    console.log('walk-through: Bitti; X 200, Y 150, Z 12 steps as alp85 script');
    await snapshots(page, snapDir, seen);
  } finally {
    rmSync(snapDir, { recursive: true, force: true });
  }
  await editor(page);
  await master(page);
  await demo(page);
  await sdk85(page);
}

// ?board=sdk85 (the selector's other board): the SDK-85's keypad and display as its description
// places them (emu/board/sdk85.h, from the SDK-85 user's manual's panel: four rows of six keys,
// the function keys on the left; six digits, four of address and two of data), no machine tool,
// and Load ROM...: a short dump refused with the ROM loader's message, the project's SDK-85 test
// program (firmware/sdk85/sdk85test.asm, as Intel HEX) taken.
async function sdk85(page) {
  const choices = await page.$$eval('#board-choice option', (os) => os.map((o) => o.value));
  assert.deepEqual(choices, ['alp85', 'sdk85'], 'the board selector');
  await page.goto(`http://127.0.0.1:${port}/?board=sdk85`);
  await page.waitForFunction(() => window.alp85?.ready, { timeout: 30000 });
  assert.equal(await page.$eval('#board-choice', (s) => s.value), 'sdk85');
  const keys = await page.$$eval('#keypad button', (bs) => bs.map((b) => ({
    key: b.dataset.key, cap: b.firstChild.textContent, row: Number(b.style.gridRow.split(' ')[0]) - 1,
    col: Number(b.style.gridColumn.split(' ')[0]) - 1 })));
  assert.equal(keys.length, 24, 'the SDK-85 has 24 keys');
  // The manual's panel: RESET VECT-INTR C D E F / SINGLE-STEP GO 8 9 A B / SUBST-MEM EXAM-REG 4 5 6 7 / NEXT EXEC 0 1 2 3.
  const panel = [['RESET', 'VECT INTR', 'C', 'D', 'E', 'F'], ['SINGLE STEP', 'GO', '8', '9', 'A', 'B'],
    ['SUBST MEM', 'EXAM REG', '4', '5', '6', '7'], ['NEXT ,', 'EXEC .', '0', '1', '2', '3']];
  for (const k of keys) assert.equal(k.cap.replace('\n', ' '), panel[k.row]?.[k.col], `key ${k.key} at row ${k.row}, column ${k.col}`);
  assert.equal(await page.$$eval('#display svg', (d) => d.length), 6, 'the SDK-85 has 6 digits');
  assert.equal(await page.$eval('#tool', (e) => getComputedStyle(e).display), 'none', 'the SDK-85 has no machine tool');
  for (const id of ['#firmware-choice', '#editor', '#demo', '#gcode'])
    assert.equal(await page.$eval(id, (e) => getComputedStyle(e).display), 'none', `${id} on the SDK-85`);
  // Load ROM...: a dump of 100 bytes is refused (a raw image is exactly 2048), shown on the page.
  const dir = mkdtempSync(join(tmpdir(), 'alp85-web-rom-'));
  try {
    const short = join(dir, 'short.bin');
    writeFileSync(short, Buffer.alloc(100, 0xFF));
    await (await page.$('#rom')).uploadFile(short);
    await page.waitForFunction(() => document.querySelector('#rom-msg').textContent !== '' &&
      !/test program/.test(document.querySelector('#rom-msg').textContent), { timeout: 10000 });
    const msg = await page.$eval('#rom-msg', (e) => e.textContent);
    assert.match(msg, /^ROM short\.bin: .*short\.bin.*100 bytes/, 'the loader\'s refusal on the page');
    // The test program as the native build assembled it, as Intel HEX: taken.
    await (await page.$('#rom')).uploadFile(process.env.ALP85_SDK85_ROM);
    await page.waitForFunction(() => /^ROM sdk85test\.hex: loaded/.test(document.querySelector('#rom-msg').textContent), { timeout: 10000 });
    console.log(`sdk85: 24 keys where the description puts them, 6 digits, no tool; Load ROM refused a short dump (${msg}) and took sdk85test.hex`);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

// The X-Y view after the thesis line: numbers at its grid lines that place the tool where the
// axes say it is, X 200 x 0.05 = 10.00 mm and Y 150 x 0.05 = 7.50 mm (to within two CSS pixels,
// the tool's rounding and a number's), and a legend whose colours are the lines drawn.
async function tableView(page) {
  const v = await page.evaluate(() => {
    const box = document.querySelector('#table-box').getBoundingClientRect();
    const nums = (id, horizontal) => [...document.querySelectorAll(`#${id} span`)].map((e) => {
      const r = e.getBoundingClientRect();
      return { mm: Number(e.textContent), at: horizontal ? (r.left + r.right) / 2 - box.left : (r.top + r.bottom) / 2 - box.top };
    });
    const d = document.querySelector('#tool-dot').getBoundingClientRect();
    return { x: nums('table-xnums', true), y: nums('table-ynums', false),
      tool: { x: (d.left + d.right) / 2 - box.left, y: (d.top + d.bottom) / 2 - box.top } };
  });
  const place = (nums, px, axis) => {
    assert.ok(nums.length >= 2, `the X-Y view has ${nums.length} ${axis} numbers`);
    const steps = nums.slice(1).map((n, i) => n.mm - nums[i].mm);
    assert.ok(steps.every((s) => Math.abs(s - steps[0]) < 1e-9 && s > 0), `${axis} numbers evenly rising: ${nums.map((n) => n.mm)}`);
    const [a, b] = [nums[0], nums[nums.length - 1]];
    const mmPerPx = (b.mm - a.mm) / (b.at - a.at);
    return { mm: a.mm + (px - a.at) * mmPerPx, px: Math.abs(mmPerPx) };
  };
  const x = place(v.x, v.tool.x, 'X'), y = place(v.y, v.tool.y, 'Y');
  assert.ok(Math.abs(x.mm - 10) <= 2 * x.px, `the X numbers put the tool at ${x.mm.toFixed(3)} mm, not 10.00`);
  assert.ok(Math.abs(y.mm - 7.5) <= 2 * y.px, `the Y numbers put the tool at ${y.mm.toFixed(3)} mm, not 7.50`);
  console.log(`X-Y view: numbers ${v.x.map((n) => n.mm)} / ${v.y.map((n) => n.mm)} mm put the tool at (${x.mm.toFixed(2)}, ${y.mm.toFixed(2)}) mm`);
  const legend = await page.evaluate(() => {
    const rgb = (c) => c.match(/\d+/g).slice(0, 3).map(Number);
    const sw = (cls, prop) => rgb(getComputedStyle(document.querySelector(`#table-legend .swatch.${cls}`))[prop]);
    // how many opaque pixels of a canvas have a colour (within 12 of each channel)
    const count = (id, [r, g, b]) => {
      const c = document.querySelector(id);
      const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let n = 0;
      for (let i = 0; i < d.length; i += 4)
        if (d[i + 3] > 200 && Math.abs(d[i] - r) <= 12 && Math.abs(d[i + 1] - g) <= 12 && Math.abs(d[i + 2] - b) <= 12) n++;
      return n;
    };
    const path = sw('path', 'borderTopColor'), ideal = sw('ideal', 'borderTopColor'), tool = sw('tool', 'backgroundColor');
    return { texts: [...document.querySelectorAll('#table-legend li')].map((li) => li.textContent),
      path: count('#table', path), ideal: count('#table-top', ideal),
      tool: JSON.stringify(tool) === JSON.stringify(rgb(getComputedStyle(document.querySelector('#tool-dot')).backgroundColor)) };
  });
  assert.equal(legend.texts.length, 3, `the X-Y view's legend: ${legend.texts}`);
  assert.match(legend.texts[0], /toolpath/);
  assert.match(legend.texts[1], /ideal line/);
  assert.match(legend.texts[2], /tool/);
  assert.ok(legend.path > 20, `the legend's toolpath colour is on ${legend.path} pixels of the path's canvas`);
  assert.ok(legend.ideal > 20, `the legend's ideal-line colour is on ${legend.ideal} pixels of the line's canvas`);
  assert.ok(legend.tool, 'the legend\'s tool is the colour of the tool');
  console.log(`X-Y view legend: ${legend.texts.join('; ')}`);
}

// The page's furniture: its icon (the project's SVG, served), the snapshot chooser's text whole,
// the editor's gutter as tall as its lines.
async function pageFurniture(page) {
  const icon = await page.evaluate(async () => {
    const l = document.querySelector('link[rel~="icon"]');
    if (!l) return null;
    const r = await fetch(l.href);
    return { status: r.status, type: r.headers.get('content-type'), text: await r.text() };
  });
  assert.ok(icon, 'the page names no icon (the browser asks for /favicon.ico: a 404)');
  assert.equal(icon.status, 200, 'the icon is not served');
  assert.match(icon.type, /^image\/svg\+xml/);
  assert.match(icon.text, /<svg[^>]*viewBox="0 0 32 32"/);
  // The chooser: its label's text all shown, the native input's own text nowhere to be cut.
  const chooser = await page.evaluate(() => {
    const label = document.querySelector('#open').closest('label');
    const input = document.querySelector('#open').getBoundingClientRect();
    return { text: label.textContent.trim(), whole: label.scrollWidth <= label.clientWidth, input: [input.width, input.height] };
  });
  assert.ok(chooser.whole, `the snapshot chooser's text "${chooser.text}" is cut`);
  assert.ok(chooser.input[0] <= 1 && chooser.input[1] <= 1, `the native file input shows (${chooser.input}): its "No file chosen" gets cut`);
  // The gutter: with the demo's source (more lines than the box shows), its box (and background)
  // as tall as its numbers, down to the last line.
  const gutter = await page.evaluate(() => {
    const g = document.querySelector('#gutter');
    return { lines: g.textContent.split('\n').length, box: g.clientHeight, content: g.scrollHeight, shown: document.querySelector('.code').clientHeight };
  });
  assert.ok(gutter.content > gutter.shown, `the source (${gutter.lines} lines) fits the box: nothing to check`);
  assert.ok(gutter.box >= gutter.content, `the gutter's background stops at ${gutter.box} of its ${gutter.content} px (${gutter.lines} lines)`);
  console.log(`icon, chooser "${chooser.text}", gutter ${gutter.lines} lines: ${gutter.box} px of ${gutter.content}`);
}

// The master program with the G-code box's path (the circle of scripts/master/circle.nc): it asks
// for the path's number and starts it (scripts/master/circle.alp's displays).
async function master(page) {
  await page.select('#firmware', 'master');
  // a word outside the subset: refused with its line and column (Q at line 2, column 5)
  await page.$eval('#gcode-text', (t) => { t.value = 'G21 G90\nG01 Q5\n'; });
  await page.click('#gcode-load');
  assert.match(await page.$eval('#gcode-msg', (d) => d.textContent), /^G-code: line 2, column 5: 'Q' is not in the subset/);
  await page.$eval('#gcode-text', (t, v) => { t.value = v; }, readFileSync(join(here, '..', '..', 'scripts', 'master', 'circle.nc'), 'utf8'));
  await page.click('#gcode-load');
  assert.match(await page.$eval('#gcode-msg', (d) => d.textContent), /^path table loaded/);
  await type(page, ['RESET']);
  await waitDisplay(page, '-ALP 85-');
  await type(page, ['R', '7', '3', '0', '0', '0', 'EXEC']);
  await waitDisplay(page, 'P=-');
  await type(page, ['1']);
  await waitDisplay(page, 'P=1');
  await type(page, ['EXEC']);
  // the display counts the segments: P=1 0001, 0002, ... (at 10x, a frame may pass more than one)
  await page.waitForFunction(() => /^P=1 00\d\d$/.test(document.querySelector('#display').dataset.text.trimEnd()),
    { timeout: 20000, polling: 'raf' });
  console.log(`master: the G-code box's circle loaded and started (${await display(page)})`);
}

// The guided demo presses its first two steps' keys: the monitor, then the thesis's Z prompt.
async function demo(page) {
  await page.click('#demo-start');
  await page.click('#demo-next');
  await waitDisplay(page, '-ALP 85-');
  await page.waitForFunction(() => !document.querySelector('#demo-next').disabled, { timeout: 20000 });
  await page.click('#demo-next');
  await waitDisplay(page, '?.=----');
  console.log('demo: Appendix C steps 1 and 2 pressed by the page');
}

// A snapshot alp85 wrote, opened by the page: the board comes back as it was saved; and the
// page's own, opened by alp85.
async function snapshots(page, snapDir, seen) {
  {
    const snap = join(snapDir, 'bitti.snap');
    assert.ok(existsSync(snap), 'alp85 script wrote no snapshot');
    await type(page, ['RESET']);  // away from Bitti first, so that the restore has to bring it back
    await waitDisplay(page, '-ALP 85-');
    const input = await page.$('#open');
    await input.uploadFile(snap);
    await waitDisplay(page, '  8itti');
    // the move that ended at Bitti is not known after the restore: no ideal line until the next
    // begins (the line from where the table stands, (10, 7.5) to (20, 15) mm, was never commanded)
    assert.equal(await page.evaluate(() => window.alp85.board.snapshot()[26]), 0, 'an ideal line after restoring Bitti');
    // a snapshot cut short is refused, with a reason in the log
    const cut = join(snapDir, 'cut.snap');
    writeFileSync(cut, readFileSync(snap).subarray(0, 40));
    await (await page.$('#open')).uploadFile(cut);
    await page.waitForFunction(() => /restore cut\.snap: .*(truncated|trailing|corrupt)/.test(document.querySelector('#log').textContent),
      { timeout: 10000 });
    assert.deepEqual(await settledAxes(page), seen, 'the restored snapshot\'s axes');
    // and the page's own snapshot: alp85's file format (ALP85SNP and its CRC-32), opened by alp85
    const bytes = await page.evaluate(() => Array.from(window.alp85.board.save()));
    writeFileSync(join(snapDir, 'page.snap'), Buffer.from(bytes));
    const back = execFileSync(alp85, ['script', '--out-dir', snapDir, join(here, 'restore.alp')], { encoding: 'utf8' });
    assert.match(back, /restored/, 'alp85 script could not restore the page\'s snapshot');
  }
  console.log('snapshots: alp85 -> page and page -> alp85');
}

async function editor(page) {
  // asm85 in the page: a deliberate error, its line and column; fixed, loaded and run.
  const good = readFileSync(join(here, '..', '..', 'firmware', 'demo', 'hello85.asm'), 'utf8');
  const lines = good.split('\n');
  const at = lines.findIndex((l) => /^\s+INX\s+H/.test(l));
  assert.ok(at > 0, 'hello85.asm has its INX H');
  const col = lines[at].indexOf('INX') + 1;
  lines[at] = lines[at].replace('INX ', 'INXX');  // no such instruction: the error is at the mnemonic
  await setSource(page, lines.join('\n'));
  await page.click('#assemble');
  const diag = await page.$eval('#diagnostics li.error', (li) => ({ line: Number(li.dataset.line), col: Number(li.dataset.col), text: li.textContent }));
  assert.equal(diag.line, at + 1, `the diagnostic's line (${diag.text})`);
  assert.equal(diag.col, col, `the diagnostic's column (${diag.text})`);
  assert.ok(await page.$eval(`#gutter`, (g, n) => g.querySelectorAll('span.error')[0]?.textContent === String(n), at + 1),
    'the error is marked at its line in the gutter');
  console.log(`asm85: ${diag.text}`);
  await setSource(page, good);
  await page.click('#assemble');
  const result = await page.$eval('#assembly-result', (li) => li.textContent);
  assert.match(result, /^assembled and loaded/, result);
  await type(page, ['RESET']);
  await waitDisplay(page, '-ALP 85-');
  await type(page, ['R', '7', '0', '8', '0', '0', 'EXEC']);
  // hello85.asm's greeting: H E L L O, blank, 8 5 (O is 3FH, the pattern of 0, as the text reads it)
  await waitDisplay(page, 'HELL0 85');
  await type(page, ['7']);
  await waitDisplay(page, 'HELL0 87');  // it echoes a hex key on the rightmost digit
  console.log('asm85: fixed, loaded, run from the monitor: HELLO 85');
}

async function setSource(page, text) {
  await page.$eval('#source', (t, v) => { t.value = v; t.dispatchEvent(new Event('input')); }, text);
}

// ---- the figures of docs/web.md -------------------------------------------------------------------
// The same workload as `alp85 bench thesis`: the thesis firmware drawing its 100 mm diagonal
// (Appendix C: Z 0, (0100, 0100) to (1514, 1514), 1000 mm/min), the physical motors (the page's,
// as alp85's), 17.152 s of machine time from EXEC. Typed once; a snapshot at the last prompt
// starts each run again.
async function figures(page, loadMs) {
  const cdp = await page.createCDPSession();
  await cdp.send('Performance.enable');
  const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
  await page.click('input[name=speed][value="0"]');
  await type(page, ['RESET']);
  await waitDisplay(page, '-ALP 85-');
  await type(page, ['R', '7', '0', '8', '0', '0', 'EXEC']);
  await waitDisplay(page, '?.=----');
  await type(page, [...'0000']);
  await waitDisplay(page, 'H1=----');
  for (const [d, next] of [['0100', 'y1='], ['0100', 'H2='], ['1514', 'y2='], ['1514', 'H=']]) {
    await type(page, [...d, 'EXEC']);
    await waitDisplay(page, `${next}----`);
  }
  await type(page, [...'1000']);
  await waitDisplay(page, 'H=1000');
  const dir = mkdtempSync(join(tmpdir(), 'alp85-web-bench-'));
  const snap = join(dir, 'h1000.alp85snap');
  writeFileSync(snap, Buffer.from(await page.evaluate(async () => Array.from(await window.alp85.board.save()))));
  const again = async (speed, exec = true) => {
    await page.click(`input[name=speed][value="${speed}"]`);
    const before = await machineT(page);  // the snapshot's time is earlier than any after it
    await (await page.$('#open')).uploadFile(snap);
    await page.waitForFunction((t) => window.alp85.t < t, { timeout: 10000 }, before);
    await waitDisplay(page, 'H=1000');
    if (exec) await page.click('#keypad button[data-key="EXEC"]');
  };
  // The CPU of 10 s of real time (1x): every chromium process (user + system, /proc) over the wall
  // time, the renderer's busy time (CDP TaskDuration) and its script; the board's ticks (60 a
  // second) and the frames drawn (only when a tick changed what the page shows).
  const realTime = async () => {
    const c0 = chromiumThreads(), m0 = await metrics(), w0 = Date.now(), t0 = await machineT(page);
    const [k0, f0, l0] = await page.evaluate(() => [window.alp85.ticks, window.alp85.frames, window.alp85.late]);
    await new Promise((r) => setTimeout(r, 10000));
    const c1 = chromiumThreads(), m1 = await metrics(), w1 = Date.now(), t1 = await machineT(page);
    const [k1, f1, l1] = await page.evaluate(() => [window.alp85.ticks, window.alp85.frames, window.alp85.late]);
    const wall = (w1 - w0) / 1000;
    const r2 = (x) => Number(x.toFixed(3));
    return { realtime_x: r2((t1 - t0) / CLOCK_HZ / wall), ticks_per_s: Number(((k1 - k0) / wall).toFixed(1)), frames_drawn_per_s: Number(((f1 - f0) / wall).toFixed(1)), frames_late: l1 - l0,
      chromium_cpu_share: r2([...c1].reduce((sum, [k, v]) => sum + v.cpu - (c0.get(k)?.cpu ?? 0), 0) / wall), threads: threadShares(c0, c1, wall), renderer_busy_share: r2((m1.TaskDuration - m0.TaskDuration) / wall),
      script_share: r2((m1.ScriptDuration - m0.ScriptDuration) / wall) };
  };
  // Real time while the table moves: from 1 s after EXEC, 10 s of the line.
  await again(1);
  await new Promise((r) => setTimeout(r, 1000));
  const p0 = await page.evaluate(() => window.alp85.pathPoints());
  const moving = await realTime();
  if (process.env.ALP85_BENCH_SHOT) await page.screenshot({ path: process.env.ALP85_BENCH_SHOT });
  if (process.env.ALP85_BENCH_TRACE) {
    await page.tracing.start({ path: process.env.ALP85_BENCH_TRACE, categories: ['devtools.timeline', 'disabled-by-default-devtools.timeline', 'toplevel', 'blink', 'cc', 'viz', 'gpu'] });
    await new Promise((r) => setTimeout(r, 3000));
    await page.tracing.stop();
  }
  moving.toolpath_points = (await page.evaluate(() => window.alp85.pathPoints())) - p0;
  // Unpaced, eight times: machine time over host time between two of the page's own samples (the
  // machine's time and the host's instant it was reached), the first right after EXEC. The first
  // runs include the browser's optimising compile of the hot WebAssembly (V8 runs it first from
  // its baseline compiler and tiers up the functions that run hot); the median of the last five
  // is the page's steady speed.
  // Beside it, per CPU second of the renderer's main thread (CDP ThreadTime), as alp85 bench
  // thesis counts its CPU seconds: what the page does with the CPU it gets on a shared host.
  const unpaced = [], unpacedCpu = [], unpacedFps = [];
  for (let i = 0; i < 8; i++) {
    await again(0);
    const m0 = await metrics(), t0 = await machineT(page);
    const [x, fps] = await page.evaluate((goal) => new Promise((ok) => {
      const a = window.alp85, t0 = a.t, h0 = a.at, f0 = a.frames;
      const poll = () => (a.t >= t0 + goal ? ok([(a.t - t0) / 3072000 / ((a.at - h0) / 1000), (a.frames - f0) / ((a.at - h0) / 1000)])
        : requestAnimationFrame(poll));
      poll();
    }), 17.152 * CLOCK_HZ);
    const t1 = await machineT(page), m1 = await metrics();
    unpaced.push(Number(x.toFixed(1)));
    unpacedFps.push(Number(fps.toFixed(1)));
    unpacedCpu.push(Number(((t1 - t0) / CLOCK_HZ / (m1.ThreadTime - m0.ThreadTime)).toFixed(1)));
  }
  // Real time with the board standing at the feed's prompt (H=1000): nothing moves.
  await again(1, false);
  await new Promise((r) => setTimeout(r, 1000));
  const standing = await realTime();
  rmSync(dir, { recursive: true, force: true });
  const median = (xs) => [...xs].sort((x, y) => x - y)[Math.floor(xs.length / 2)];
  const native = execFileSync(alp85, ['bench', 'thesis'], { encoding: 'utf8' }).match(/^physical .*$/m)?.[0];
  console.log(JSON.stringify({ wasm_bytes: readFileSync(join(site, 'alp85.wasm')).length, js_bytes: readFileSync(join(site, 'alp85.js')).length,
    load_ms: loadMs, unpaced_x: unpaced, unpaced_median_last5_x: median(unpaced.slice(3)), unpaced_median_last5_x_per_cpu_s: median(unpacedCpu.slice(3)), unpaced_fps: unpacedFps, unpaced_x_per_cpu_s: unpacedCpu,
    realtime_moving: moving, realtime_standing: standing, native, loadavg: readFileSync('/proc/loadavg', 'utf8').split(' ').slice(0, 3).join(' ') }, null, 1));
}

// CPU seconds (user + system) of the browser and all its descendants, from /proc, thread by
// thread ("renderer CrRendererMain": the page's main thread, "renderer Compositor", "gpu-process
// VizCompositorTh": software compositing, ...).
function chromiumThreads() {
  const root = browser.process().pid;
  const tick = 100;  // USER_HZ on Linux
  const procs = new Map();
  const stat = (path) => {
    const text = readFileSync(path, 'utf8');
    const f = text.slice(text.lastIndexOf(')') + 2).split(' ');
    return { comm: text.slice(text.indexOf('(') + 1, text.lastIndexOf(')')), ppid: Number(f[1]), cpu: (Number(f[11]) + Number(f[12])) / tick };
  };
  for (const d of readdirSync('/proc')) {
    if (!/^\d+$/.test(d)) continue;
    try { procs.set(Number(d), stat(`/proc/${d}/stat`)); } catch { /* gone */ }
  }
  const out = new Map();
  for (const pid of procs.keys()) {
    let ours = false;
    for (let q = pid, hops = 0; q && hops < 10; q = procs.get(q)?.ppid, hops++) if (q === root) { ours = true; break; }
    if (!ours) continue;
    try {
      const type = readFileSync(`/proc/${pid}/cmdline`, 'utf8').match(/--type=([a-z-]+)/)?.[1] ?? 'browser';
      for (const t of readdirSync(`/proc/${pid}/task`)) {
        const s = stat(`/proc/${pid}/task/${t}/stat`);
        out.set(`${pid}/${t}`, { name: `${type} ${s.comm === 'chromium' ? 'main' : s.comm}`, cpu: s.cpu });
      }
    } catch { /* gone */ }
  }
  return out;
}
// The share of a core each kind of thread took between two readings, the largest first.
function threadShares(before, after, wall) {
  const by = new Map();
  for (const [k, v] of after) by.set(v.name, (by.get(v.name) ?? 0) + (v.cpu - (before.get(k)?.cpu ?? 0)) / wall);
  return Object.fromEntries([...by].filter(([, v]) => v >= 0.005).sort((x, y) => y[1] - x[1]).map(([k, v]) => [k, Number(v.toFixed(3))]));
}
