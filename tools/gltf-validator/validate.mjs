// Validates glTF files with the Khronos glTF-Validator.
// Usage: node validate.mjs [--at-least N] FILE_OR_DIR...
// A directory stands for the .glb and .gltf files in it. Prints one line per file; exits
// 1 if any file has an error or a warning, or fewer than N files were found; 2 on misuse.
import { readFile, readdir, stat } from 'node:fs/promises';
import { join } from 'node:path';
import validator from 'gltf-validator';

const args = process.argv.slice(2);
let atLeast = 1;
if (args[0] === '--at-least') {
  atLeast = Number(args[1]);
  args.splice(0, 2);
}
if (args.length === 0 || !Number.isInteger(atLeast)) {
  console.error('usage: node validate.mjs [--at-least N] FILE_OR_DIR...');
  process.exit(2);
}
const files = [];
for (const arg of args) {
  if ((await stat(arg)).isDirectory()) {
    const names = (await readdir(arg)).filter((n) => /\.(glb|gltf)$/.test(n)).sort();
    files.push(...names.map((n) => join(arg, n)));
  } else {
    files.push(arg);
  }
}
let failed = false;
for (const file of files) {
  const bytes = new Uint8Array(await readFile(file));
  const report = await validator.validateBytes(bytes, { uri: file, maxIssues: 50 });
  const { numErrors, numWarnings, numInfos, messages } = report.issues;
  console.log(`${file}: ${numErrors} errors, ${numWarnings} warnings, ${numInfos} infos`);
  for (const m of messages) {
    if (m.severity <= 1) console.log(`  ${m.severity === 0 ? 'error' : 'warning'} ${m.code} ${m.pointer ?? ''}: ${m.message}`);
  }
  if (numErrors > 0 || numWarnings > 0) failed = true;
}
console.log(`${files.length} files validated`);
if (files.length < atLeast) {
  console.log(`expected at least ${atLeast} files`);
  failed = true;
}
process.exit(failed ? 1 : 0);
