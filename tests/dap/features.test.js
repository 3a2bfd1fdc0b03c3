// The rest of `alp85 dap`'s requests through DebugClient: entry, function/conditional/hit-count/
// log-point breakpoints, reverseContinue, goto, setVariable, memory, disassembly, the console, a
// runaway program, TCP, pause, restart, terminate. Expected values are worked out by hand from
// firmware/thesis/thesis.asm for the line (0100, 0050) -> (0300, 0200) of session.test.js:
// |M| = 0.75, YID(X) = 50 + floor(0.75 X) - 75, one step per loop, Y when YAC != YID, else X:
//   XAC 100 X, 101 X, 102 Y (YAC 50->51), 102 X, 103 Y (51->52), 103 X, 104 Y (52->53), 104 X,
//   105 X (YID 53 = YAC), 106 ...
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const cp = require('node:child_process');
const fs = require('node:fs');
const os = require('node:os');
const path = require('node:path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const ALP85 = process.env.ALP85 || path.resolve(__dirname, '../../build/bin/alp85');
const THESIS = path.resolve(__dirname, '../../firmware/thesis/thesis.asm');
const lines = fs.readFileSync(THESIS, 'utf8').split('\n');
const lineOf = (re) => {
  const i = lines.findIndex((l) => re.test(l));
  assert.ok(i >= 0, `${re} is in thesis.asm`);
  return i + 1;
};
const L = {
  out: lineOf(/^OUT:\s+LXI\s+H,1B39H\s+; L629/),
  yinc: lineOf(/^YINC:\s+LHLD\s+1B32H\s+; L751/),
  yid: lineOf(/^YID:\s+LHLD\s+1B34H\s+; L570/),
};
const KEYS = 'R 7 0800 EXEC 0000 0100 EXEC 0050 EXEC 0300 EXEC 0200 EXEC 1500 EXEC';

async function stopAfter(dc, request) {
  const stopped = dc.waitForEvent('stopped');
  await request;
  return (await stopped).body;
}
async function top(dc) {
  return (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames[0];
}
async function bytesAt(dc, memoryReference, count) {
  const r = await dc.customRequest('readMemory', { memoryReference, count });
  return [...Buffer.from(r.body.data, 'base64')];
}
async function scopeVars(dc, name) {
  const frame = await top(dc);
  const s = (await dc.scopesRequest({ frameId: frame.id })).body.scopes.find((x) => x.name === name);
  return (await dc.variablesRequest({ variablesReference: s.variablesReference })).body.variables;
}
const value = (vars, name) => vars.find((v) => v.name === name).value;

async function started(args) {
  const dc = new DebugClient(ALP85, 'dap', 'alp85', undefined, true);
  dc.defaultTimeout = 20000;
  await dc.start();
  dc.exited = new Promise((resolve) => dc._adapterProcess.on('exit', (code, signal) => resolve({ code, signal })));
  await dc.initializeRequest({ adapterID: 'alp85' });
  const initialized = dc.waitForEvent('initialized');
  await dc.launchRequest(args);
  await initialized;
  return dc;
}

async function finished(dc) {
  await dc.disconnectRequest({});
  assert.deepEqual(await dc.exited, { code: 0, signal: null });
}

test('entry, breakpoints of every kind, reverseContinue, goto, setVariable, memory, disassembly, console', async () => {
  const dc = await started({ program: THESIS, defines: { FIXED: 1 }, motor: 'ideal', realTime: false, keys: KEYS, stopOnEntry: true });
  try {
    // RESET leaves the PC at 0000H (8085 data sheet): the monitor's first instruction.
    let stop = await stopAfter(dc, dc.configurationDoneRequest());
    assert.equal(stop.reason, 'entry');
    assert.equal((await top(dc)).instructionPointerReference, '0x0000');
    // 0000H (the monitor's JMP COLD) has no label, and KMODE EQU 0 is a constant: the frame is
    // named by its address alone, once.
    assert.equal((await top(dc)).name, '0000H');

    // A function breakpoint with a hit count: the third OUT is the one after two X steps.
    let r = await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'OUT', hitCondition: '3' }] });
    assert.equal(r.body.breakpoints[0].verified, true);
    assert.equal(r.body.breakpoints[0].line, L.out);
    stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.deepEqual(await bytesAt(dc, 'YAC', 4), [50, 0, 102, 0]); // YAC = 50, XAC = 102

    // A log point in YINC and a conditional breakpoint at YID (XAC = 106): three Y steps logged
    // on the way, with YAC before each increment, 50, 51, 52; then YID with XAC = 106, YAC = 53.
    await dc.setFunctionBreakpointsRequest({ breakpoints: [] });
    r = await dc.setBreakpointsRequest({
      source: { path: THESIS },
      breakpoints: [{ line: L.yinc, logMessage: 'YAC was {word[YAC]}' }, { line: L.yid, condition: 'word[1B34H] == 106' }],
    });
    assert.ok(r.body.breakpoints.every((b) => b.verified));
    const logs = [];
    dc.on('output', (e) => {
      if (e.body.output.startsWith('YAC was')) logs.push(e.body.output.trim());
    });
    stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.equal((await top(dc)).line, L.yid);
    assert.deepEqual(await bytesAt(dc, 'YAC', 4), [53, 0, 106, 0]);
    assert.deepEqual(logs, ['YAC was 0032H (50)', 'YAC was 0033H (51)', 'YAC was 0034H (52)']);

    // A bad condition is refused with its column; a bad hit condition too.
    r = await dc.setBreakpointsRequest({ source: { path: THESIS }, breakpoints: [{ line: L.yid, condition: 'word[ == 1' }, { line: L.yid, hitCondition: 'often' }] });
    assert.equal(r.body.breakpoints[0].verified, false);
    assert.match(r.body.breakpoints[0].message, /column/);
    assert.equal(r.body.breakpoints[1].verified, false);

    // reverseContinue: back to the last Y step, YINC entered with YAC = 52 at XAC = 104.
    await dc.setBreakpointsRequest({ source: { path: THESIS }, breakpoints: [{ line: L.yinc }] });
    stop = await stopAfter(dc, dc.reverseContinueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.equal((await top(dc)).line, L.yinc);
    assert.deepEqual(await bytesAt(dc, 'YAC', 4), [52, 0, 104, 0]);
    let ev = await dc.evaluateRequest({ expression: 'word[XAC]', context: 'watch' });
    assert.equal(ev.body.result, '0068H (104)');
    ev = await dc.evaluateRequest({ expression: 'YAC', context: 'hover' });
    assert.equal(ev.body.result, '0034H (52) at 1B32H');

    // goto: the PC to OUT's first line.
    const targets = await dc.gotoTargetsRequest({ source: { path: THESIS }, line: L.out });
    stop = await stopAfter(dc, dc.gotoRequest({ threadId: 1, targetId: targets.body.targets[0].id }));
    assert.equal(stop.reason, 'goto');
    assert.equal((await top(dc)).line, L.out);

    // setVariable: A and the carry flag.
    const regsRef = (await dc.scopesRequest({ frameId: (await top(dc)).id })).body.scopes.find((s) => s.name === 'Registers').variablesReference;
    r = await dc.setVariableRequest({ variablesReference: regsRef, name: 'A', value: '12H' });
    assert.match(r.body.value, /^12H/);
    assert.match(value(await scopeVars(dc, 'Registers'), 'A'), /^12H/);
    r = await dc.setVariableRequest({ variablesReference: regsRef, name: 'A', value: '300' }).catch((e) => e);
    assert.match(String(r.message ?? r), /does not fit/);

    // writeMemory, readMemory; disassembly of OUT: LXI H,1B39H is 21H 39H 1BH (operand low byte first).
    await dc.customRequest('writeMemory', { memoryReference: '0x1B40', data: Buffer.from([1, 2, 3]).toString('base64') });
    assert.deepEqual(await bytesAt(dc, '0x1B40', 3), [1, 2, 3]);
    const dis = await dc.disassembleRequest({ memoryReference: 'OUT', instructionCount: 2 });
    assert.equal(dis.body.instructions[0].instruction, 'LXI H,1B39H');
    assert.equal(dis.body.instructions[0].instructionBytes, '21 39 1B');
    assert.equal(dis.body.instructions[0].line, L.out);
    assert.equal(dis.body.instructions[1].instruction, 'MOV A,M');

    // The console: the debugger's commands and the command language; a bad line is an error.
    ev = await dc.evaluateRequest({ expression: 'expect reg A 12H', context: 'repl' });
    assert.equal(ev.success, true);
    ev = await dc.evaluateRequest({ expression: 'expect reg A 13H', context: 'repl' }).catch((e) => e);
    assert.match(String(ev.message ?? ev), /13/);
    ev = await dc.evaluateRequest({ expression: 'no such command here', context: 'repl' }).catch((e) => e);
    assert.ok(ev instanceof Error);

    // The display, the machine tool's axes and the 8155 as scopes: during the motion the display
    // is blank; X has made 4 steps (100 -> 104) and Y 3 (50 -> 53: YINC counts the step OUT has
    // just made); port A is an output (the monitor's RESET command 01H), port B an input.
    assert.equal(value(await scopeVars(dc, 'Display'), 'text'), '"        "');
    const tool = await scopeVars(dc, 'Machine tool');
    assert.match(value(tool, 'X'), /^4 steps/);
    assert.match(value(tool, 'Y'), /^3 steps/);
    assert.match(value(await scopeVars(dc, '8155'), 'command'), /port A out, port B in/);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
  }
});

test('a program that runs into unprogrammed memory stops with an exception', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'alp85-dap-'));
  const src = path.join(dir, 'away.asm');
  fs.writeFileSync(src, '        ORG     0800H\nSTART:  MVI     A,1\n        JMP     0F00H\n        END     START\n');
  const dc = await started({ program: src, monitor: false, realTime: false });
  try {
    const stop = await stopAfter(dc, dc.configurationDoneRequest());
    assert.equal(stop.reason, 'exception');
    assert.match(stop.text, /0F00H/);
    // Stopped before the fetch at 0F00H, naming the jump that left the program (0802H).
    assert.equal((await top(dc)).instructionPointerReference, '0x0F00');
    assert.match(stop.text, /after 0802H \(JMP 0F00H\)/);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

// One expression language (issue 22): a convenience variable set at the debug console is read by a
// breakpoint's condition each time it is checked: with $N = 9 `$N < 5` is false at every OUT and the
// run goes on to Bitti's HLT; with $N = 3, reverseContinue stops at the last OUT.
test('a breakpoint condition reads a convenience variable of the console', async () => {
  const dc = await started({ program: THESIS, defines: { FIXED: 1 }, motor: 'ideal', realTime: false, keys: KEYS, stopOnEntry: true });
  try {
    await stopAfter(dc, dc.configurationDoneRequest());
    let r = await dc.evaluateRequest({ expression: 'set $N = 9', context: 'repl' });
    assert.ok(r.success);
    r = await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'OUT', condition: '$N < 5' }] });
    assert.equal(r.body.breakpoints[0].verified, true, r.body.breakpoints[0].message);
    r = await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'OUT', condition: '$NOSUCH < 5' }] });
    assert.equal(r.body.breakpoints[0].verified, false);
    await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'OUT', condition: '$N < 5' }] });
    // $N = 9: the motion runs past every OUT to Bitti, where the firmware halts: reported as such.
    let stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'halted');
    assert.match(stop.text, /HLT at [0-9A-F]{4}H/);
    // $N = 3: going back, the last OUT is a stop.
    await dc.evaluateRequest({ expression: 'set $N = 3', context: 'repl' });
    stop = await stopAfter(dc, dc.reverseContinueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.equal((await top(dc)).line, L.out);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
  }
});

// The 8155's port C mode as DAP's scope and the console's `info 8155` show it: one field of the
// 8155's own description. Command 05H sets port A out, port B in and bits 3-2 = 01, which the
// 8155/8156 data sheet's command register table names ALT3 (00 ALT1, 11 ALT2, 01 ALT3, 10 ALT4).
test('the 8155 scope and info 8155 show the same port C mode: ALT3 for bits 01', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'alp85-dap-'));
  const src = path.join(dir, 'alt3.asm');
  fs.writeFileSync(src, '        ORG     0800H\nSTART:  MVI     A,05H\n        OUT     0F8H\nHERE:   JMP     HERE\n        END     START\n');
  const dc = await started({ program: src, monitor: false, realTime: false });
  try {
    await dc.setBreakpointsRequest({ source: { path: src }, breakpoints: [{ line: 4 }] });
    const stop = await stopAfter(dc, dc.configurationDoneRequest());
    assert.equal(stop.reason, 'breakpoint');
    const command = (await scopeVars(dc, '8155')).find((v) => v.name === 'command');
    assert.match(command.value, /^05H: port A out, port B in, port C ALT3 /);
    const fields = (await dc.variablesRequest({ variablesReference: command.variablesReference })).body.variables;
    const dapMode = value(fields, 'port C');
    assert.match(dapMode, /^bits 3-2 = 01: ALT3 /);
    const info = (await dc.evaluateRequest({ expression: 'info 8155', context: 'repl' })).body.result;
    const line = info.split('\n').find((l) => /^\s+port C\s+bits 3-2/.test(l));
    assert.ok(line, info);
    assert.equal(line.trim().replace(/^port C\s+/, ''), dapMode);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

// A pause during a long reverseContinue: the adapter reads messages between the slices of the
// re-execution, so the pause ends it within 100 ms, where it has got to (not at the start of the
// history it would have reached). 200 s of machine time at the monitor's prompt are the history
// (40 under the sanitizers: tests/CMakeLists.txt, ALP85_LONG_HISTORY_S); SOBE is never reached
// while the firmware waits for keys, so reverseContinue would re-execute all of it: about 1.3 s
// in the release build, 9 s under the sanitizers, against the pause's 0.3 s.
const HISTORY_S = Number(process.env.ALP85_LONG_HISTORY_S || 200);
test('pause ends a long reverseContinue at once', async () => {
  const dc = await started({ firmware: 'thesis-fixed', realTime: false, stopOnEntry: true });
  try {
    await stopAfter(dc, dc.configurationDoneRequest());
    let r = await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'SOBE' }] });
    assert.equal(r.body.breakpoints[0].verified, true, r.body.breakpoints[0].message);
    // the console's command moved the machine
    const ran = dc.waitForEvent('stopped', 120000);
    r = await dc.evaluateRequest({ expression: `run ${HISTORY_S}s`, context: 'repl' });
    assert.ok(r.success);
    await ran;
    const stopped = dc.waitForEvent('stopped');
    const going = dc.reverseContinueRequest({ threadId: 1 });
    await new Promise((res) => setTimeout(res, 300));
    const asked = Date.now();
    await dc.pauseRequest({ threadId: 1 });
    const stop = (await stopped).body;
    const ms = Date.now() - asked;
    await going;
    assert.equal(stop.reason, 'pause');
    assert.ok(ms < 100, `the pause took ${ms} ms`);
    // Somewhere inside the history: neither at its start (0) nor at its end.
    const t = Number((await dc.evaluateRequest({ expression: '$T', context: 'repl' })).body.result.match(/\d+/g).pop());
    assert.ok(t > 0 && t < HISTORY_S * 3072000, `T = ${t}`);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
  }
});

test('over TCP: paced to the board clock, pause, restart, terminate', async () => {
  const server = cp.spawn(ALP85, ['dap', '--port', '0'], { stdio: ['ignore', 'ignore', 'pipe'] });
  const exited = new Promise((resolve) => server.on('exit', (code, signal) => resolve({ code, signal })));
  try {
    const port = await new Promise((resolve, reject) => {
      let text = '';
      server.stderr.on('data', (d) => {
        text += d;
        const m = /listening on 127\.0\.0\.1:(\d+)/.exec(text);
        if (m) resolve(Number(m[1]));
      });
      setTimeout(() => reject(new Error('no port announced')), 5000).unref();
    });
    const dc = new DebugClient('node', '', 'alp85');
    await dc.start(port);
    await dc.initializeRequest({ adapterID: 'alp85' });
    const initialized = dc.waitForEvent('initialized');
    await dc.launchRequest({ firmware: 'thesis-fixed' }); // the monitor, real time
    await initialized;
    const host0 = Date.now();
    await dc.configurationDoneRequest();
    await new Promise((r) => setTimeout(r, 200));
    let stop = await stopAfter(dc, dc.pauseRequest({ threadId: 1 }));
    const host = (Date.now() - host0) / 1000;
    assert.equal(stop.reason, 'pause');
    // Paced: the board has run about as long as the host has - a run runs a 10 ms slice, then
    // waits until the host's clock has caught up, so it is at most a slice or two ahead (an
    // unpaced run does some 60 times more).
    const tstates = (vars) => Number(vars.find((v) => v.name === 'T-states').value);
    const intRef = (await scopeVars(dc, 'Registers')).find((v) => v.name === 'interrupts').variablesReference;
    const t1 = tstates((await dc.variablesRequest({ variablesReference: intRef })).body.variables);
    assert.ok(t1 > 0 && t1 / 3.072e6 <= host + 0.03, `${t1} T-states in ${host} s`);

    const restarted = dc.restartRequest({});
    await restarted;
    stop = await stopAfter(dc, dc.pauseRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'pause');
    const terminated = dc.waitForEvent('terminated');
    await dc.terminateRequest({});
    await terminated;
    await dc.disconnectRequest({});
    assert.deepEqual(await exited, { code: 0, signal: null });
  } finally {
    server.kill();
  }
});

// Two breakpoints at one address (a source line and a function breakpoint on its label): a stop
// there names both, going forward and going back (reverseContinue replays the history to the
// last position where breakpoints stop, and every breakpoint at that position stopped it).
test('reverseContinue names every breakpoint at the address, as a forward stop does', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'alp85-dap-'));
  const src = path.join(dir, 'twice.asm');
  fs.writeFileSync(src, '        ORG     0800H\nSTART:  LXI     SP,2000H\nLOOP:   CALL    SUB\n        JMP     LOOP\nSUB:    INR     A\n        RET\n        END     START\n');
  const dc = await started({ program: src, monitor: false, realTime: false, stopOnEntry: true });
  try {
    await stopAfter(dc, dc.configurationDoneRequest());
    const line = (await dc.setBreakpointsRequest({ source: { path: src }, breakpoints: [{ line: 5 }] })).body.breakpoints[0];
    const fn = (await dc.setFunctionBreakpointsRequest({ breakpoints: [{ name: 'SUB' }] })).body.breakpoints[0];
    assert.ok(line.verified && fn.verified);
    const both = [line.id, fn.id].sort((a, b) => a - b);
    const ids = (stop) => [...(stop.hitBreakpointIds ?? [])].sort((a, b) => a - b);
    let stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.deepEqual(ids(stop), both);
    // The second time round (LOOP calls SUB again): both again; then back to the first.
    stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.deepEqual(ids(stop), both);
    stop = await stopAfter(dc, dc.reverseContinueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    assert.equal((await top(dc)).line, 5);
    assert.deepEqual(ids(stop), both);
    await finished(dc);
  } finally {
    dc._adapterProcess.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});

// A run typed in the debug console is a resumable run, as the continue request's: the evaluate is
// answered at once, pause stops it within a slice (20 ms of host time), the machine's state can
// not be asked for while it runs, and disconnect ends the session during one.
test('the debug console\'s runs go on between messages: pause and disconnect are answered at once', async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'alp85-dap-'));
  const src = path.join(dir, 'spin.asm');
  // 0800H MVI A,1 (2 bytes), 0802H MVI B,2, 0804H MVI C,3, 0806H HERE: JMP HERE.
  fs.writeFileSync(src, '        ORG     0800H\nSTART:  MVI     A,1\n        MVI     B,2\n        MVI     C,3\nHERE:   JMP     HERE\n        END     START\n');
  const dc = await started({ program: src, monitor: false, realTime: false, stopOnEntry: true });
  try {
    await stopAfter(dc, dc.configurationDoneRequest());
    // stepi 3: three instructions, PC at HERE (0806H); told in the answer, with a stopped event.
    let stop = await stopAfter(dc, dc.evaluateRequest({ expression: 'stepi 3', context: 'repl' }));
    assert.equal(stop.reason, 'step');
    assert.equal((await top(dc)).instructionPointerReference, '0x0806');

    // finish with no CALL on the stack: nothing to run to, an error at once.
    let r = await dc.evaluateRequest({ expression: 'finish', context: 'repl' }).catch((e) => e);
    assert.match(String(r.message ?? r), /no caller/);

    // run 3000s: 3000 s of board time take seconds of host time; pause 0.5 s in.
    let t0 = Date.now();
    r = await dc.evaluateRequest({ expression: 'run 3000s', context: 'repl' });
    assert.ok(Date.now() - t0 < 1000, `evaluate answered after ${Date.now() - t0} ms`);
    assert.match(r.body.result, /Running for 3000s/);
    await new Promise((res) => setTimeout(res, 500));
    r = await dc.customRequest('stackTrace', { threadId: 1 }).catch((e) => e);
    assert.match(String(r.message ?? r), /running/);
    t0 = Date.now();
    stop = await stopAfter(dc, dc.pauseRequest({ threadId: 1 }));
    const ms = Date.now() - t0;
    assert.equal(stop.reason, 'pause');
    assert.ok(ms < 1000, `pause answered after ${ms} ms`);
    assert.equal((await top(dc)).instructionPointerReference, '0x0806');

    // run 10ms ends by itself: 10 ms = 30720 T-states at 3.072 MHz, reported as a step.
    stop = await stopAfter(dc, dc.evaluateRequest({ expression: 'run 10ms', context: 'repl' }));
    assert.equal(stop.reason, 'step');

    // continue typed in the console: a breakpoint at HERE ends it (the console's description
    // is its output).
    await dc.setBreakpointsRequest({ source: { path: src }, breakpoints: [{ line: 5 }] });
    stop = await stopAfter(dc, dc.evaluateRequest({ expression: 'continue', context: 'repl' }));
    assert.equal(stop.reason, 'breakpoint');
    await dc.setBreakpointsRequest({ source: { path: src }, breakpoints: [] });
    r = await dc.evaluateRequest({ expression: 'run for 1s', context: 'repl' });
    assert.match(r.body.result, /Running for 1s/);
    r = await dc.evaluateRequest({ expression: 'run 5 lightyears', context: 'repl' }).catch((e) => e);
    assert.match(String(r.message ?? r), /running|bad time/);

    // run 100000s, then disconnect: answered, and the adapter ends at once.
    await dc.pauseRequest({ threadId: 1 });
    r = await dc.evaluateRequest({ expression: 'run 100000s', context: 'repl' });
    assert.match(r.body.result, /Running/);
    t0 = Date.now();
    await dc.disconnectRequest({});
    assert.deepEqual(await dc.exited, { code: 0, signal: null });
    assert.ok(Date.now() - t0 < 2000, `disconnect took ${Date.now() - t0} ms`);
  } finally {
    dc._adapterProcess.kill();
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
