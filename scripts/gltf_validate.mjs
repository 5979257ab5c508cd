#!/usr/bin/env node
// Validates glTF 2.0 files (.gltf with their external buffers/images, .glb) with the Khronos
// glTF-Validator, all in one node process, and prints one row per file.
//
//   node scripts/gltf_validate.mjs [--json] [--strict] FILE|DIR...
//
// A DIR is searched recursively for .gltf and .glb files. Output (stdout): a TSV with the header
//   path  errors  warnings  infos  hints  codes
// where codes lists the distinct error and warning codes as CODE*count; or, with --json, one JSON
// array of {path, errors, warnings, infos, hints, codes, failure}. A file the validator cannot
// read at all (not glTF, not GLB, unreadable) counts one error and says why in failure.
// Exit status: 0; 1 with --strict when any file has an error; 2 on a usage error.
// The validator comes from scripts/node_modules (scripts/setup.sh runs `npm ci` there).

import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const USAGE = 'usage: node scripts/gltf_validate.mjs [--json] [--strict] FILE|DIR...';
const SEVERITY_ERROR = 0;
const SEVERITY_WARNING = 1;

function loadValidator() {
  const require = createRequire(import.meta.url);
  try {
    return require('gltf-validator');
  } catch (err) {
    process.stderr.write('gltf_validate: the gltf-validator package is not installed; ' +
                         'run scripts/setup.sh (npm ci in scripts/)\n');
    process.exit(2);
  }
}

function parseArgs(argv) {
  const options = { json: false, strict: false, inputs: [] };
  for (const arg of argv) {
    if (arg === '--json') options.json = true;
    else if (arg === '--strict') options.strict = true;
    else if (arg === '--help' || arg === '-h') { process.stdout.write(USAGE + '\n'); process.exit(0); }
    else if (arg.startsWith('--')) { process.stderr.write(`gltf_validate: unknown option ${arg}\n${USAGE}\n`); process.exit(2); }
    else options.inputs.push(arg);
  }
  if (options.inputs.length === 0) { process.stderr.write(USAGE + '\n'); process.exit(2); }
  return options;
}

function isGltfName(name) {
  return /\.(gltf|glb)$/i.test(name);
}

// Files named on the command line are kept whatever their extension; directories give their
// .gltf/.glb files, sorted so that runs compare line by line.
function collectFiles(inputs) {
  const files = [];
  const walk = (dir) => {
    for (const entry of fs.readdirSync(dir, { withFileTypes: true }).sort((a, b) => a.name.localeCompare(b.name))) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (entry.isFile() && isGltfName(entry.name)) files.push(full);
    }
  };
  for (const input of inputs) {
    if (fs.existsSync(input) && fs.statSync(input).isDirectory()) walk(input);
    else files.push(input);
  }
  return files;
}

function externalResourceReader(file) {
  return (uri) => new Promise((resolve, reject) => {
    const resource = path.resolve(path.dirname(file), decodeURIComponent(uri));
    fs.readFile(resource, (err, data) => (err ? reject(err.toString()) : resolve(new Uint8Array(data))));
  });
}

function issueCodes(messages) {
  const counts = new Map();
  for (const m of messages) {
    if (m.severity !== SEVERITY_ERROR && m.severity !== SEVERITY_WARNING) continue;
    counts.set(m.code, (counts.get(m.code) || 0) + 1);
  }
  return [...counts.entries()].sort((a, b) => a[0].localeCompare(b[0])).map(([c, n]) => `${c}*${n}`);
}

async function validateFile(validator, file) {
  const row = { path: file, errors: 0, warnings: 0, infos: 0, hints: 0, codes: [], failure: '' };
  try {
    const data = new Uint8Array(fs.readFileSync(file));
    const report = await validator.validateBytes(data, {
      uri: path.basename(file),
      maxIssues: 0,
      writeTimestamp: false,
      externalResourceFunction: externalResourceReader(file),
    });
    const issues = report.issues;
    Object.assign(row, { errors: issues.numErrors, warnings: issues.numWarnings,
                         infos: issues.numInfos, hints: issues.numHints,
                         codes: issueCodes(issues.messages) });
  } catch (err) {
    row.errors = 1;
    row.failure = String(err).split('\n')[0];
  }
  return row;
}

function printTsv(rows) {
  const lines = ['path\terrors\twarnings\tinfos\thints\tcodes'];
  for (const r of rows) {
    const codes = r.failure ? `FAILED: ${r.failure}` : r.codes.join(',');
    lines.push([r.path, r.errors, r.warnings, r.infos, r.hints, codes.replace(/[\t\n]/g, ' ')].join('\t'));
  }
  process.stdout.write(lines.join('\n') + '\n');
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const validator = loadValidator();
  const rows = [];
  for (const file of collectFiles(options.inputs)) rows.push(await validateFile(validator, file));
  if (options.json) process.stdout.write(JSON.stringify(rows, null, 1) + '\n');
  else printTsv(rows);
  const withErrors = rows.filter((r) => r.errors > 0).length;
  process.stderr.write(`gltf_validate: ${rows.length} files, ${withErrors} with errors ` +
                       `(validator ${validator.version()})\n`);
  process.exit(options.strict && withErrors > 0 ? 1 : 0);
}

main();
