// `alp85 dap` driven by a real DAP client (@vscode/debugadapter-testsupport's DebugClient), as an
// editor drives it: the thesis firmware (thesis-fixed: thesis.asm with FIXED=1) assembled on the
// fly, a line drawn from (0100, 0050) to (0300, 0200) at 1500 mm/min (docs/thesis.md).
//
// Every expected value is worked out by hand from firmware/thesis/thesis.asm (comments say how);
// line numbers are found in the source text by the statement's own words.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { DebugClient } = require('@vscode/debugadapter-testsupport');

const ALP85 = process.env.ALP85 || path.resolve(__dirname, '../../build/bin/alp85');
const THESIS = path.resolve(__dirname, '../../firmware/thesis/thesis.asm');
const lines = fs.readFileSync(THESIS, 'utf8').split('\n');
function lineOf(re) {
  const i = lines.findIndex((l) => re.test(l));
  assert.ok(i >= 0, `${re} is in thesis.asm`);
  return i + 1;
}

const L = {
  out: lineOf(/^OUT:\s+LXI\s+H,1B39H\s+; L629/),      // OUT's first instruction
  callOut: lineOf(/^\s+CALL\s+OUT\s+; L31/),          // the main loop's CALL OUT
  o00: lineOf(/^O00:\s+CALL\s+COMPAR\s+; L662/),      // quadrant 0: compare the Y's
  jnzO41: lineOf(/^\s+JNZ\s+O41\s+; L663/),
  compar: lineOf(/^COMPAR:\s+LHLD\s+1B30H\s+; L716/),
  yincStore: lineOf(/^\s+SHLD\s+1B32H\s+; L753/),     // YINC: YAC + 1 stored
  yincRet: lineOf(/^\s+RET\s+; L754/),
};

// Z = 0, X1 = 0100, Y1 = 0050, X2 = 0300, Y2 = 0200, feedrate 1500 (D = 1); the last EXEC starts
// the motion (docs/thesis.md, "Entering values").
const launchArgs = {
  program: THESIS,
  defines: { FIXED: 1 },
  motor: 'ideal',
  realTime: false,
  keys: 'R 7 0800 EXEC 0000 0100 EXEC 0050 EXEC 0300 EXEC 0200 EXEC 1500 EXEC',
};

function named(vars, name) {
  const v = vars.find((x) => x.name === name);
  assert.ok(v, `variable ${name} among ${vars.map((x) => x.name).join(', ')}`);
  return v.value;
}

async function scope(dc, frameId, name) {
  const scopes = (await dc.scopesRequest({ frameId })).body.scopes;
  const s = scopes.find((x) => x.name === name);
  assert.ok(s, `scope ${name}`);
  return (await dc.variablesRequest({ variablesReference: s.variablesReference })).body.variables;
}

async function flags(dc, frameId) {
  const regs = await scope(dc, frameId, 'Registers');
  const f = regs.find((x) => x.name === 'F');
  return (await dc.variablesRequest({ variablesReference: f.variablesReference })).body.variables;
}

async function frames(dc) {
  return (await dc.stackTraceRequest({ threadId: 1 })).body.stackFrames;
}

// Sends a request and waits for the stopped event it causes.
async function stopAfter(dc, request) {
  const stopped = dc.waitForEvent('stopped');
  await request;
  return (await stopped).body;
}

async function bytesAt(dc, memoryReference, count) {
  const r = await dc.customRequest('readMemory', { memoryReference, count });
  return [...Buffer.from(r.body.data, 'base64')];
}

test('a session on the thesis firmware: breakpoints, stack, registers, steps, data breakpoint, step back, keys', async () => {
  const dc = new DebugClient(ALP85, 'dap', 'alp85', undefined, true);
  dc.defaultTimeout = 20000;
  await dc.start();
  let gone = false;
  const exited = new Promise((resolve) =>
    dc._adapterProcess.on('exit', (code, signal) => {
      gone = true;
      resolve({ code, signal });
    }));
  try {
    const init = await dc.initializeRequest({ adapterID: 'alp85', linesStartAt1: true, columnsStartAt1: true });
    assert.equal(init.body.supportsStepBack, true);
    assert.equal(init.body.supportsDataBreakpoints, true);

    const initialized = dc.waitForEvent('initialized');
    await dc.launchRequest(launchArgs);
    await initialized;

    // A breakpoint on the comment line above OUT binds to OUT's first instruction, and says so.
    const set = await dc.setBreakpointsRequest({ source: { path: THESIS }, breakpoints: [{ line: L.out - 1 }] });
    assert.equal(set.body.breakpoints[0].verified, true);
    assert.equal(set.body.breakpoints[0].line, L.out);
    assert.match(set.body.breakpoints[0].message, /moved/);

    let stop = await stopAfter(dc, dc.configurationDoneRequest());
    assert.equal(stop.reason, 'breakpoint');

    // The first OUT: called from the main loop with SP = 20B0H (MAIN's LXI SP; COORD, SPEED and
    // BASLA have returned; ANA jumps to CMAIN), so two frames and SP = 20AEH.
    let stack = await frames(dc);
    assert.equal(stack.length, 2);
    assert.equal(stack[0].line, L.out);
    assert.match(stack[0].name, /^OUT/);
    assert.equal(stack[0].source.path, THESIS);
    assert.equal(stack[1].line, L.callOut);

    // OKEY returned NZ at its first test: A = X2 low (2CH, 300) XOR XAC low (64H, 100) = 48H,
    // HL = 1B34H (XAC). 48H has two one-bits: S = 0, Z = 0, P = 1; XRA clears CY.
    let regs = await scope(dc, stack[0].id, 'Registers');
    assert.match(named(regs, 'A'), /^48H/);
    assert.match(named(regs, 'HL'), /^1B34H/);
    assert.match(named(regs, 'SP'), /^20AEH/);
    let f = await flags(dc, stack[0].id);
    assert.equal(named(f, 'Z'), '0');
    assert.equal(named(f, 'S'), '0');
    assert.equal(named(f, 'P'), '1');
    assert.equal(named(f, 'CY'), '0');

    // Both signs are + (1B39H = 1B3AH = 00H): quadrant 0, OUT goes on to O00's CALL COMPAR.
    await dc.setBreakpointsRequest({ source: { path: THESIS }, breakpoints: [{ line: L.out }, { line: L.o00 }] });
    stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'breakpoint');
    stack = await frames(dc);
    assert.equal(stack[0].line, L.o00);

    // Step in: COMPAR, three frames deep.
    stop = await stopAfter(dc, dc.stepInRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'step');
    stack = await frames(dc);
    assert.equal(stack.length, 3);
    assert.equal(stack[0].line, L.compar);
    assert.equal(stack[1].line, L.o00);
    assert.equal(stack[2].line, L.callOut);

    // Step out: back in OUT after the CALL. YIDV = Y1 = 50 (at XAC = X1 the slope terms cancel)
    // and YAC = Y1 = 50: DE = HL = 0032H, SUB E = 0 (RNZ falls through), SBB D = 0: A = 0, Z = 1.
    stop = await stopAfter(dc, dc.stepOutRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'step');
    stack = await frames(dc);
    assert.equal(stack.length, 2);
    assert.equal(stack[0].line, L.jnzO41);
    regs = await scope(dc, stack[0].id, 'Registers');
    assert.match(named(regs, 'A'), /^00H/);
    assert.match(named(regs, 'HL'), /^0032H/);
    assert.match(named(regs, 'DE'), /^0032H/);
    f = await flags(dc, stack[0].id);
    assert.equal(named(f, 'Z'), '1');

    // A data breakpoint on YAC (1B32H), the firmware's actual Y, written with a new value.
    await dc.setBreakpointsRequest({ source: { path: THESIS }, breakpoints: [] });
    const vars = await scope(dc, stack[0].id, 'Firmware variables');
    assert.match(named(vars, 'YAC'), /^0032H/);
    const scopes = (await dc.scopesRequest({ frameId: stack[0].id })).body.scopes;
    const fwRef = scopes.find((s) => s.name === 'Firmware variables').variablesReference;
    const info = await dc.dataBreakpointInfoRequest({ name: 'YAC', variablesReference: fwRef });
    assert.equal(info.body.dataId, '1B32H:2');
    assert.ok(info.body.accessTypes.includes('write'));
    const dbp = await dc.setDataBreakpointsRequest({ breakpoints: [{ dataId: info.body.dataId, accessType: 'write' }] });
    assert.equal(dbp.body.breakpoints[0].verified, true);

    // |M| = 150/200 = 0.75 (exact in 16.16), YID(X) = 50 + floor(0.75 X) - 75. This OUT steps X
    // (XAC 101); YID(101) = 50 = YAC: X again (102); YID(102) = 50 + 76 - 75 = 51 > YAC: a Y step,
    // and INPUT's YINC stores YAC = 51 (0033H). The stop is after that SHLD, at YINC's RET.
    stop = await stopAfter(dc, dc.continueRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'data breakpoint');
    stack = await frames(dc);
    assert.equal(stack[0].line, L.yincRet);
    assert.deepEqual(await bytesAt(dc, '0x1B32', 4), [0x33, 0x00, 102, 0x00]); // YAC = 51, XAC = 102

    // Step back: before the SHLD, YAC is 50 again in memory; HL already holds 51.
    stop = await stopAfter(dc, dc.stepBackRequest({ threadId: 1 }));
    assert.equal(stop.reason, 'step');
    stack = await frames(dc);
    assert.equal(stack[0].line, L.yincStore);
    assert.deepEqual(await bytesAt(dc, '0x1B32', 2), [0x32, 0x00]);
    regs = await scope(dc, stack[0].id, 'Registers');
    assert.match(named(regs, 'HL'), /^0033H/);

    // A key pressed from the debug console: during the motion the firmware reads no keys, so the
    // 8279 keeps it in its FIFO: one entry, row 0 return line 5 = 05H (docs/peripherals.md).
    await dc.setDataBreakpointsRequest({ breakpoints: [] });
    const ev = await dc.evaluateRequest({ expression: 'press 5', context: 'repl' });
    assert.equal(ev.success, true);
    const kdc = await scope(dc, (await frames(dc))[0].id, '8279');
    assert.equal(named(kdc, 'FIFO count'), '1');
    assert.equal(named(kdc, 'FIFO'), '05H');

    await dc.disconnectRequest({});
    assert.deepEqual(await exited, { code: 0, signal: null });
  } finally {
    if (!gone) await dc.stop(); // after a failure: the adapter is still there
  }
});
