// ALP85's VS Code extension: runs `alp85 dap` (the path from the alp85.path setting) as the
// debug adapter for "type": "alp85". Everything else is in package.json and in alp85 itself.
'use strict';
const vscode = require('vscode');

function activate(context) {
  context.subscriptions.push(
    vscode.debug.registerDebugAdapterDescriptorFactory('alp85', {
      createDebugAdapterDescriptor() {
        const alp85 = vscode.workspace.getConfiguration('alp85').get('path') || 'alp85';
        return new vscode.DebugAdapterExecutable(alp85, ['dap']);
      },
    }),
    // F5 on an .asm without a launch.json: debug that file.
    vscode.debug.registerDebugConfigurationProvider('alp85', {
      resolveDebugConfiguration(folder, config) {
        if (!config.type && !config.request && !config.name) {
          const editor = vscode.window.activeTextEditor;
          if (!editor || !editor.document.fileName.match(/\.(asm|a85)$/i)) return config;
          return { type: 'alp85', request: 'launch', name: 'ALP 85: debug this file', program: editor.document.fileName, keys: 'R 7 0800 EXEC' };
        }
        return config;
      },
    }));
}

function deactivate() {}

module.exports = { activate, deactivate };
