// An independent programming-port client for tests/fx.rs: the node-fxplc package from npm
// (n-car/node-fxplc, installed by .ci/run), over its TCP transport to a served simulator.
// Usage: node node_fxplc.mjs PACKAGE_DIR HOST PORT 'JSON list of operations'
// Operations: {"op":"readNumber"|"writeNumber"|"readBit"|"writeBit","reg":"D1000","value":…}.
// Prints one JSON line: the results in order ({"value": …} or {"error": "ErrorClass"}).
import { pathToFileURL } from 'node:url';
import path from 'node:path';

const [pkg, host, port, opsJson] = process.argv.slice(2);
const fx = await import(pathToFileURL(path.join(pkg, 'dist', 'esm', 'index.js')).href);
const transport = new fx.TransportTCP({ host, port: Number(port), timeout: 2000, flushDelay: 0 });
await transport.connect();
const plc = new fx.FXPLCClient(transport, { timeoutMs: 3000 });
const out = [];
for (const o of JSON.parse(opsJson)) {
  try {
    let value = null;
    if (o.op === 'readNumber') value = await plc.readNumber(o.reg, fx.NumberType.WordSigned);
    else if (o.op === 'writeNumber') await plc.writeNumber(o.reg, o.value, fx.NumberType.WordSigned);
    else if (o.op === 'readBit') value = await plc.readBit(o.reg);
    else if (o.op === 'writeBit') await plc.writeBit(o.reg, o.value);
    else throw new Error('unknown op ' + o.op);
    out.push({ value });
  } catch (e) {
    out.push({ error: e?.constructor?.name ?? String(e) });
  }
}
console.log(JSON.stringify(out));
plc.close();
process.exit(0);
