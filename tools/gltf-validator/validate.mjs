// Validates one glTF/GLB file with the Khronos validator; prints the report's issue counts
// as JSON and exits 1 when there are errors. Usage: node validate.mjs FILE
import { readFile } from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

const file = process.argv[2];
const data = new Uint8Array(await readFile(file));
const dir = path.dirname(file);
const report = await validator.validateBytes(data, {
  uri: path.basename(file),
  externalResourceFunction: (uri) =>
    readFile(path.join(dir, decodeURIComponent(uri))).then((b) => new Uint8Array(b)),
});
const errors = report.issues.messages.filter((m) => m.severity === 0);
console.log(JSON.stringify({
  errors: report.issues.numErrors,
  warnings: report.issues.numWarnings,
  messages: errors.slice(0, 5).map((m) => `${m.code} ${m.pointer ?? ""}: ${m.message}`),
}));
process.exit(report.issues.numErrors > 0 ? 1 : 0);
