// Node smoke test of the installed package, run from the temporary app (scripts/test.d/
// npm-package.sh copies it there next to smoke.mjs): `import 'screwbender'` goes through the
// package's "exports" exactly as in a user's project.
import init, * as sb from 'screwbender';
import { runSmoke } from './smoke.mjs';

await init(); // harmless in Node (the "node" entry has already instantiated the module)
const result = runSmoke(sb);
for (const c of result.checks) console.log(`${c.ok ? 'ok  ' : 'FAIL'} ${c.name}: ${c.detail}`);
console.log(`node smoke: ${result.ok ? 'passed' : 'FAILED'}`);
process.exit(result.ok ? 0 : 1);
