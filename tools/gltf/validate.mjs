// Validates .glb files with the Khronos glTF validator (npm gltf-validator): one line per file,
// "FILE: E errors, W warnings, I infos", the errors' codes and messages after it; exit 1 when any
// file has an error (or cannot be read).
//   node tools/gltf/validate.mjs FILE.glb...
import { readFileSync } from 'node:fs';
import validator from 'gltf-validator';

let bad = 0;
for (const file of process.argv.slice(2)) {
    try {
        const report = await validator.validateBytes(new Uint8Array(readFileSync(file)), { maxIssues: 50 });
        const n = report.issues;
        console.log(`${file}: ${n.numErrors} errors, ${n.numWarnings} warnings, ${n.numInfos} infos`);
        for (const m of n.messages) if (m.severity === 0 || process.env.GLTF_VERBOSE) console.log(`  ${m.code}: ${m.message} (${m.pointer ?? ''})`);
        if (n.numErrors > 0) bad++;
    } catch (e) {
        console.log(`${file}: cannot be validated: ${e}`);
        bad++;
    }
}
process.exit(bad ? 1 : 0);
