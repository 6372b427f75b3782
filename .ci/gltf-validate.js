// Validates a glTF 2.0 file (.glb or .gltf with its buffers) with the Khronos validator (npm
// `gltf-validator`); exits 1 on any error. Used by the tests through BRINE_GLTF_VALIDATOR.
const v = require('gltf-validator');
const fs = require('fs');
const path = process.argv[2];
const data = new Uint8Array(fs.readFileSync(path));
v.validateBytes(data, {externalResourceFunction: (uri) => new Promise((res, rej) => {
  try { res(new Uint8Array(fs.readFileSync(require('path').join(require('path').dirname(path), decodeURIComponent(uri))))); } catch (e) { rej(e.toString()); }
})}).then(r => {
  console.log(JSON.stringify({errors: r.issues.numErrors, warnings: r.issues.numWarnings, infos: r.issues.numInfos, messages: r.issues.messages.slice(0, 8)}, null, 1));
  process.exit(r.issues.numErrors > 0 ? 1 : 0);
}).catch(e => { console.error(e); process.exit(2); });
