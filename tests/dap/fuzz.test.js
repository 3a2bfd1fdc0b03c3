// Nothing a client sends ends an `alp85 dap` session: malformed frames, text that is not JSON,
// JSON that is not a request, unknown commands, arguments of the wrong type, and requests out of
// order (before initialize, before launch, while running) each get an error response, and the
// adapter still answers a well-formed request afterwards. A seeded generator mutates real requests
// (property: every request with a seq is answered, with that request_seq, within the time limit).
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const cp = require('node:child_process');
const path = require('node:path');

const ALP85 = process.env.ALP85 || path.resolve(__dirname, '../../build/bin/alp85');
const THESIS = path.resolve(__dirname, '../../firmware/thesis/thesis.asm');

// A raw client: bytes out, framed messages in.
class Raw {
  constructor() {
    this.proc = cp.spawn(ALP85, ['dap'], { stdio: ['pipe', 'pipe', 'inherit'] });
    this.buf = Buffer.alloc(0);
    this.messages = [];
    this.waiters = [];
    this.exit = new Promise((resolve) => this.proc.on('exit', (code, signal) => resolve({ code, signal })));
    this.proc.stdout.on('data', (d) => {
      this.buf = Buffer.concat([this.buf, d]);
      for (;;) {
        const end = this.buf.indexOf('\r\n\r\n');
        if (end < 0) break;
        const m = /Content-Length: (\d+)/i.exec(this.buf.subarray(0, end).toString());
        assert.ok(m, 'every frame from the adapter has a Content-Length');
        const n = Number(m[1]);
        if (this.buf.length < end + 4 + n) break;
        this.messages.push(JSON.parse(this.buf.subarray(end + 4, end + 4 + n).toString()));
        this.buf = this.buf.subarray(end + 4 + n);
      }
      this.waiters = this.waiters.filter((w) => !w());
    });
    this.proc.stdin.on('error', () => {});
    this.seq = 1000;
  }
  bytes(b) {
    this.proc.stdin.write(b);
  }
  frame(text) {
    this.bytes(`Content-Length: ${Buffer.byteLength(text)}\r\n\r\n${text}`);
  }
  // Resolves with the first message (from now on) that `pred` accepts; fails after 5 s.
  until(pred, what) {
    const from = this.messages.length;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`no ${what} within 5 s`)), 5000);
      const check = () => {
        const m = this.messages.slice(from).find(pred);
        if (m) {
          clearTimeout(timer);
          resolve(m);
          return true;
        }
        return false;
      };
      if (!check()) this.waiters.push(check);
    });
  }
  // Sends a request and returns its response.
  request(command, args, extra = {}) {
    const seq = ++this.seq;
    const r = this.until((m) => m.type === 'response' && m.request_seq === seq, `response to ${command} (${seq})`);
    this.frame(JSON.stringify({ seq, type: 'request', command, arguments: args, ...extra }));
    return r;
  }
  // An error response to something that has no seq of its own (request_seq 0).
  refusal() {
    return this.until((m) => m.type === 'response' && m.request_seq === 0 && m.success === false, 'error response');
  }
}

// Deterministic: a small LCG, so a failure can be replayed.
function rng(seed) {
  let s = seed >>> 0;
  return () => (s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 2 ** 32;
}

const weird = [null, true, 0, -1, 2 ** 53, 1.5, '', 'x', '0x1B32', 'YAC', [], [1, 'a'], {}, { path: 5 }, 'a'.repeat(3000)];

const templates = [
  ['initialize', { adapterID: 'alp85' }],
  ['launch', { program: THESIS, defines: { FIXED: 1 }, realTime: false }],
  ['setBreakpoints', { source: { path: THESIS }, breakpoints: [{ line: 703 }] }],
  ['setFunctionBreakpoints', { breakpoints: [{ name: 'OUT' }] }],
  ['setInstructionBreakpoints', { breakpoints: [{ instructionReference: '0x0800' }] }],
  ['setExceptionBreakpoints', { filters: ['runaway'] }],
  ['dataBreakpointInfo', { name: 'YAC' }],
  ['setDataBreakpoints', { breakpoints: [{ dataId: '1B32H:2', accessType: 'write' }] }],
  ['breakpointLocations', { source: { path: THESIS }, line: 700, endLine: 710 }],
  ['configurationDone', {}],
  ['continue', { threadId: 1 }],
  ['next', { threadId: 1 }],
  ['stepIn', { threadId: 1 }],
  ['stepOut', { threadId: 1 }],
  ['stepBack', { threadId: 1 }],
  ['reverseContinue', { threadId: 1 }],
  ['pause', { threadId: 1 }],
  ['gotoTargets', { source: { path: THESIS }, line: 703 }],
  ['goto', { threadId: 1, targetId: 0x801 }],
  ['threads', {}],
  ['stackTrace', { threadId: 1, startFrame: 0, levels: 20 }],
  ['scopes', { frameId: 1 }],
  ['variables', { variablesReference: 1 }],
  ['setVariable', { variablesReference: 1, name: 'A', value: '12H' }],
  ['evaluate', { expression: 'HL', context: 'watch' }],
  ['evaluate', { expression: 'info 8279', context: 'repl' }],
  ['readMemory', { memoryReference: '0x1B30', count: 16 }],
  ['writeMemory', { memoryReference: '0x1B40', data: 'AAEC' }],
  ['disassemble', { memoryReference: '0x0800', instructionOffset: -4, instructionCount: 10 }],
  ['source', { sourceReference: 1 }],
  ['restart', {}],
  ['noSuchRequest', {}],
];

function mutate(args, r) {
  const out = JSON.parse(JSON.stringify(args));
  const keys = Object.keys(out);
  const pick = () => weird[Math.floor(r() * weird.length)];
  if (keys.length === 0 || r() < 0.2) out[`extra${Math.floor(r() * 3)}`] = pick();
  for (const k of keys) if (r() < 0.5) out[k] = pick();
  return r() < 0.1 ? pick() : out;
}

test('malformed and out-of-order requests get error responses; the session goes on', { timeout: 60000 }, async () => {
  const c = new Raw();
  try {
    // Before initialize.
    let r = await c.request('launch', { program: THESIS });
    assert.equal(r.success, false);
    assert.match(r.message, /before 'initialize'/);
    r = await c.request('stackTrace', { threadId: 1 });
    assert.equal(r.success, false);

    // Frames and bodies that are not requests.
    c.frame('{"seq": 3, "type": "request", "command": ');
    assert.match((await c.refusal()).message, /not JSON/);
    c.frame('[1, 2, 3]');
    assert.match((await c.refusal()).message, /not a request/);
    c.frame('"just a string"');
    await c.refusal();
    c.frame('');
    await c.refusal();
    c.bytes('X-Other: 1\r\n\r\n');
    assert.match((await c.refusal()).message, /without Content-Length/);
    c.bytes('Content-Length: twelve\r\n\r\n');
    assert.match((await c.refusal()).message, /not a number/);
    c.frame('\u0000\u0001\u00ff garbage \ud800');
    await c.refusal();
    r = await c.request(undefined, {});
    assert.equal(r.success, false);
    r = await c.request('noSuchRequest', {});
    assert.equal(r.success, false);
    assert.match(r.message, /unknown request 'noSuchRequest'/);

    // Initialize, then the rest out of order: nothing before launch.
    r = await c.request('initialize', { adapterID: 'alp85' });
    assert.equal(r.success, true);
    r = await c.request('initialize', { adapterID: 'alp85' });
    assert.equal(r.success, false);
    for (const cmd of ['configurationDone', 'continue', 'next', 'stepBack', 'stackTrace', 'scopes', 'readMemory', 'evaluate']) {
      r = await c.request(cmd, {});
      assert.equal(r.success, false, cmd);
    }
    // Wrong types and missing files.
    r = await c.request('launch', { program: 5 });
    assert.match(r.message, /'program' must be a string/);
    r = await c.request('launch', { program: '/no/such/file.asm' });
    assert.match(r.message, /no such file/);
    r = await c.request('launch', { program: THESIS, defines: { FIXED: 1 }, realTime: false, motor: 'diesel' });
    assert.match(r.message, /motor/);
    r = await c.request('setBreakpoints', { source: { path: THESIS }, breakpoints: [{ line: 'x' }] });
    assert.match(r.message, /'line' must be an integer/);

    // A real launch; requests while running; then the generator.
    r = await c.request('launch', { program: THESIS, defines: { FIXED: 1 }, realTime: false, keys: 'R 7 0800 EXEC' });
    assert.equal(r.success, true);
    r = await c.request('launch', { program: THESIS });
    assert.match(r.message, /already launched/);
    r = await c.request('configurationDone', {});
    assert.equal(r.success, true);
    r = await c.request('stackTrace', { threadId: 1 });
    assert.match(r.message, /running/);
    const paused = c.until((m) => m.event === 'stopped' && m.body.reason === 'pause', 'stopped (pause)');
    r = await c.request('pause', { threadId: 1 });
    assert.equal(r.success, true);
    await paused;

    const r01 = rng(0x8085);
    for (let i = 0; i < 400; ++i) {
      const [cmd, args] = templates[Math.floor(r01() * templates.length)];
      // Runs that could take long are paused at once; everything is answered.
      r = await c.request(cmd, r01() < 0.7 ? mutate(args, r01) : args);
      assert.equal(r.type, 'response');
      if (!r.success) assert.ok(typeof r.message === 'string' && r.message.length > 0, `${cmd}: a message`);
      if (cmd === 'continue' || cmd === 'next' || cmd === 'stepOut') await c.request('pause', { threadId: 1 });
    }

    // Still alive and sane.
    r = await c.request('threads', {});
    assert.equal(r.success, true);
    assert.equal(r.body.threads[0].name, '8085');
    r = await c.request('disconnect', {});
    assert.equal(r.success, true);
    assert.deepEqual(await c.exit, { code: 0, signal: null });
  } finally {
    c.proc.kill();
  }
});

test('an oversized frame is refused without reading it into memory, and the input ending ends the adapter', { timeout: 20000 }, async () => {
  const c = new Raw();
  try {
    c.bytes('Content-Length: 999999999\r\n\r\n');
    assert.match((await c.refusal()).message, /at most/);
    c.proc.stdin.end();
    assert.deepEqual(await c.exit, { code: 1, signal: null }); // input ended without a disconnect
  } finally {
    c.proc.kill();
  }
});

// Every field of a request with a type of its own, given another: an error response each, and the
// adapter goes on. A seq that is not an integer cannot be echoed: its response has request_seq 0.
test('a request whose seq, command, arguments or argument has the wrong type gets an error response', { timeout: 60000 }, async () => {
  const c = new Raw();
  const nextResponse = () => c.until((m) => m.type === 'response', 'a response');
  try {
    const badSeqs = ['abc', null, '5', [], {}, true, 1.5, [1], undefined];
    for (const command of ['initialize', 'threads', 'disconnect']) {
      for (const seq of badSeqs) {
        const r = nextResponse();
        c.frame(JSON.stringify(seq === undefined ? { type: 'request', command } : { seq, type: 'request', command, arguments: {} }));
        const m = await r;
        assert.equal(m.success, false, `seq ${JSON.stringify(seq)}`);
        assert.equal(m.request_seq, 0);
        assert.match(m.message, /"seq" must be an integer/);
      }
    }
    // An integer too large for a signed 64-bit number (2^64 - 1) cannot be echoed either.
    {
      const r = nextResponse();
      c.frame('{"seq": 18446744073709551615, "type": "request", "command": "threads"}');
      const m = await r;
      assert.equal(m.request_seq, 0);
      assert.match(m.message, /"seq" must be an integer/);
    }
    for (const command of [5, null, true, [], {}, ['threads']]) {
      const r = nextResponse();
      c.frame(JSON.stringify({ seq: 77, type: 'request', command }));
      const m = await r;
      assert.equal(m.success, false);
      assert.equal(m.request_seq, 77);
    }
    for (const args of ['x', 5, true, [], [1, 2]]) {
      const r = await c.request('threads', args);
      assert.equal(r.success, false, JSON.stringify(args));
      assert.match(r.message, /"arguments" must be an object/);
    }
    let r = await c.request('initialize', { adapterID: 'alp85' });
    assert.equal(r.success, true);
    r = await c.request('launch', { program: THESIS, defines: { FIXED: 1 }, realTime: false, stopOnEntry: true });
    assert.equal(r.success, true);
    r = await c.request('configurationDone', {});
    assert.equal(r.success, true);
    // Arguments of the wrong type, read or not by the adapter (there is one thread, but a threadId
    // must be an integer all the same).
    const wrong = [
      ['setBreakpoints', { source: { path: THESIS }, breakpoints: 'line 5' }, /'breakpoints' must be an array/],
      ['setBreakpoints', { source: { path: THESIS }, breakpoints: [5] }, /'breakpoints' must hold objects/],
      ['setBreakpoints', { source: 'thesis.asm', breakpoints: [] }, /'source' must be an object/],
      ['setBreakpoints', { source: { path: 5 }, breakpoints: [] }, /'path' must be a string/],
      ['setBreakpoints', { source: { path: THESIS, sourceReference: 'x' }, breakpoints: [] }, /'sourceReference'/],
      ['setBreakpoints', { source: { path: THESIS }, breakpoints: [{ line: 700, column: 'x' }] }, /'column'/],
      ['setBreakpoints', { source: { path: THESIS }, breakpoints: [{ line: 700, condition: 5 }] }, /'condition'/],
      ['setFunctionBreakpoints', { breakpoints: { name: 'OUT' } }, /'breakpoints' must be an array/],
      ['setInstructionBreakpoints', { breakpoints: [null] }, /'breakpoints' must hold objects/],
      ['setDataBreakpoints', { breakpoints: [{ dataId: 7 }] }, /'dataId'/],
      ['setExceptionBreakpoints', { filters: 'runaway' }, /'filters' must be an array/],
      ['next', { threadId: '1' }, /'threadId' must be an integer/],
      ['stepIn', { threadId: 1, granularity: 3 }, /'granularity'/],
      ['stepBack', { threadId: 1, singleThread: 'yes' }, /'singleThread'/],
      ['stackTrace', { threadId: [] }, /'threadId'/],
      ['stackTrace', { threadId: 1, levels: '20' }, /'levels'/],
      ['scopes', { frameId: '1' }, /'frameId'/],
      ['variables', { variablesReference: {} }, /'variablesReference'/],
      ['evaluate', { expression: ['A'] }, /'expression'/],
      ['evaluate', { expression: 'A', context: 1 }, /'context'/],
      ['evaluate', { expression: 'A', frameId: 'top' }, /'frameId'/],
      ['readMemory', { memoryReference: 4096, count: 4 }, /'memoryReference'/],
      ['readMemory', { memoryReference: '0x1000', count: '4' }, /'count'/],
      ['disassemble', { memoryReference: '0x0800', instructionCount: 2, resolveSymbols: 'no' }, /'resolveSymbols'/],
      ['gotoTargets', { source: { path: THESIS }, line: '700' }, /'line'/],
      ['goto', { threadId: 1, targetId: '0x801' }, /'targetId'/],
      ['disconnect', { restart: 'no' }, /'restart'/],
      ['disconnect', { terminateDebuggee: 1 }, /'terminateDebuggee'/],
    ];
    for (const [command, args, message] of wrong) {
      r = await c.request(command, args);
      assert.equal(r.success, false, `${command} ${JSON.stringify(args)}`);
      assert.match(r.message, message, `${command} ${JSON.stringify(args)}`);
    }
    // Still alive: a request answered, then disconnect ends the session as it should.
    r = await c.request('threads', {});
    assert.equal(r.success, true);
    r = await c.request('disconnect', {});
    assert.equal(r.success, true);
    assert.deepEqual(await c.exit, { code: 0, signal: null });
  } finally {
    c.proc.kill();
  }
});

// One bad frame with a body costs one error response: the adapter drops its body (and any stray
// bytes) up to the next Content-Length header and reads the frames after it as sent.
test('after a bad frame with a body the adapter reads the next frames and disconnect ends it', { timeout: 60000 }, async () => {
  const body = JSON.stringify({ seq: 5, type: 'request', command: 'threads' });
  const n = Buffer.byteLength(body);
  const bad = {
    'no Content-Length': `X-Other: 1\r\n\r\n${body}`,
    abc: `Content-Length: abc\r\n\r\n${body}`,
    '-5': `Content-Length: -5\r\n\r\n${body}`,
    '+2': `Content-Length: +${n}\r\n\r\n${body}`,
    '1e3': `Content-Length: 1e3\r\n\r\n${body}`,
    'a tab': `Content-Length:\t${n}\r\n\r\n${body}`,
    'LF-only header': `Content-Length: ${n}\n\n${body}`,
    'extra bytes after a body': `Content-Length: ${n}\r\n\r\n${body}}}}`,
  };
  for (const [what, wire] of Object.entries(bad)) {
    const c = new Raw();
    try {
      let r = await c.request('initialize', { adapterID: 'alp85' });
      assert.equal(r.success, true, what);
      const refused = c.refusal();
      c.bytes(wire);
      await refused;
      r = await c.request('threads', {});
      assert.equal(r.success, true, what);
      r = await c.request('threads', {});
      assert.equal(r.success, true, what);
      r = await c.request('disconnect', {});
      assert.equal(r.success, true, what);
      assert.deepEqual(await c.exit, { code: 0, signal: null }, what);
      assert.equal(c.messages.filter((m) => m.type === 'response' && m.request_seq === 0).length, 1, `${what}: one error response`);
    } finally {
      c.proc.kill();
    }
  }
});
