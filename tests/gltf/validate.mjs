// Runs the Khronos glTF validator (npm gltf-validator, installed into node_modules/ by
// scripts/deps.sh node) on each file given and prints every message it reports.
//
//   node tests/gltf/validate.mjs [--strict] FILE.glb ... [--no-strict FILE.glb ...]
//
// Exit status: 0 when no file has an error or a warning (nor an info or a hint for the
// files after --strict, until --no-strict), 1 otherwise, 2 on bad usage or an unreadable file, 77 (ctest's skip code) when
// the validator is not installed.
//
// Other modules add their GLBs to the ctest check with sk_gltf_check() in
// tests/gltf/CMakeLists.txt (see docs/gltf.md, "Validating").
import { createRequire } from 'node:module';
import { existsSync, readFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const validatorDir = join(here, '..', '..', 'node_modules', 'gltf-validator');
const severities = ['error', 'warning', 'info', 'hint'];

const files = [];
let strictMode = false;
let badOption = false;
for (const a of process.argv.slice(2)) {
  if (a === '--strict' || a === '--no-strict') strictMode = a === '--strict';
  else if (a.startsWith('--')) badOption = true;
  else files.push({ path: a, strict: strictMode });
}
if (files.length === 0 || badOption) {
  console.error('usage: node tests/gltf/validate.mjs [--strict] FILE.glb ... [--no-strict FILE.glb ...]');
  process.exit(2);
}
if (!existsSync(join(validatorDir, 'package.json'))) {
  console.log(`skip: the glTF validator is not installed (${validatorDir}); run scripts/deps.sh node`);
  process.exit(77);
}
const validator = createRequire(import.meta.url)(validatorDir);

let failed = false;
for (const { path: file, strict } of files) {
  let bytes;
  try {
    bytes = new Uint8Array(readFileSync(file));
  } catch (e) {
    console.error(`${file}: cannot read (${e.message})`);
    process.exit(2);
  }
  // maxIssues 0 = report every issue
  const report = await validator.validateBytes(bytes, { uri: basename(file), maxIssues: 0 });
  const issues = report.issues;
  const counts = [issues.numErrors, issues.numWarnings, issues.numInfos, issues.numHints];
  for (const m of issues.messages) {
    console.log(`${file}: ${severities[m.severity]} ${m.code} at ${m.pointer ?? m.offset ?? '-'}: ${m.message}`);
  }
  const info = report.info ?? {};
  console.log(
    `${file}: ${counts[0]} errors, ${counts[1]} warnings, ${counts[2]} infos, ${counts[3]} hints` +
      ` (validator ${report.validatorVersion}; ${info.drawCallCount ?? 0} draw calls,` +
      ` ${info.totalVertexCount ?? 0} vertices, ${info.animationCount ?? 0} animations,` +
      ` ${info.materialCount ?? 0} materials, skins: ${info.hasSkins ? 'yes' : 'no'},` +
      ` morph targets: ${info.hasMorphTargets ? 'yes' : 'no'}, textures: ${info.hasTextures ? 'yes' : 'no'})`
  );
  if (counts[0] > 0 || counts[1] > 0 || (strict && (counts[2] > 0 || counts[3] > 0))) failed = true;
}
process.exit(failed ? 1 : 0);
