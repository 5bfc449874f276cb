// Starts `reach lsp` for .reach files: diagnostics, completion, hover,
// definitions, references, and the answers of a run as code lenses.
const vscode = require("vscode");
const { LanguageClient } = require("vscode-languageclient/node");

let client;

function activate(context) {
  const command = vscode.workspace.getConfiguration("reach").get("path") || "reach";
  client = new LanguageClient(
    "reach",
    "reach",
    { command, args: ["lsp"] },
    { documentSelector: [{ scheme: "file", language: "reach" }, { scheme: "untitled", language: "reach" }] }
  );
  context.subscriptions.push(client);
  return client.start();
}

function deactivate() {
  return client ? client.stop() : undefined;
}

module.exports = { activate, deactivate };
