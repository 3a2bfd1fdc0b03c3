// editors/vscode: the extension contributes the alp85 debugger with a launch snippet for .asm
// files and runs `alp85 dap`; each launch attribute it offers is one the adapter reads and
// docs/editors.md explains.
'use strict';
const { test } = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const Module = require('node:module');

const ROOT = path.resolve(__dirname, '../..');
const pkg = JSON.parse(fs.readFileSync(path.join(ROOT, 'editors/vscode/package.json'), 'utf8'));

test('package.json contributes the debugger, its .asm language and a launch snippet', () => {
  const dbg = pkg.contributes.debuggers.find((d) => d.type === 'alp85');
  assert.ok(dbg);
  assert.ok(pkg.contributes.languages.some((l) => l.extensions.includes('.asm') && dbg.languages.includes(l.id)));
  assert.ok(pkg.contributes.breakpoints.some((b) => dbg.languages.includes(b.language)));
  assert.ok(dbg.configurationSnippets.length >= 1);
  assert.ok(dbg.configurationSnippets.every((s) => s.body.type === 'alp85' && s.body.request === 'launch'));
  assert.ok(pkg.activationEvents.includes('onDebugResolve:alp85'));
});

test('every launch attribute is read by the adapter and explained in docs/editors.md', () => {
  const attrs = Object.keys(pkg.contributes.debuggers[0].configurationAttributes.launch.properties);
  const adapter = fs.readFileSync(path.join(ROOT, 'emu/dap/launch.cpp'), 'utf8');
  const doc = fs.readFileSync(path.join(ROOT, 'docs/editors.md'), 'utf8');
  for (const a of attrs) {
    assert.ok(adapter.includes(`"${a}"`), `launch.cpp reads ${a}`);
    assert.ok(doc.includes(`\`${a}\``), `docs/editors.md explains ${a}`);
  }
});

test('the extension starts `alp85 dap` with the configured path', () => {
  const registered = {};
  const fakeVscode = {
    debug: {
      registerDebugAdapterDescriptorFactory: (type, f) => (registered.factory = { type, f }),
      registerDebugConfigurationProvider: (type, p) => (registered.provider = { type, p }),
    },
    workspace: { getConfiguration: () => ({ get: () => '/opt/alp85/bin/alp85' }) },
    window: { activeTextEditor: { document: { fileName: '/x/prog.asm' } } },
    DebugAdapterExecutable: class {
      constructor(command, args) {
        Object.assign(this, { command, args });
      }
    },
  };
  const load = Module._load;
  Module._load = (req, ...rest) => (req === 'vscode' ? fakeVscode : load(req, ...rest));
  try {
    const ext = require(path.join(ROOT, 'editors/vscode/extension.js'));
    ext.activate({ subscriptions: [] });
  } finally {
    Module._load = load;
  }
  assert.equal(registered.factory.type, 'alp85');
  const d = registered.factory.f.createDebugAdapterDescriptor();
  assert.equal(d.command, '/opt/alp85/bin/alp85');
  assert.deepEqual(d.args, ['dap']);
  const cfg = registered.provider.p.resolveDebugConfiguration(undefined, {});
  assert.equal(cfg.program, '/x/prog.asm');
  assert.equal(cfg.type, 'alp85');
});
