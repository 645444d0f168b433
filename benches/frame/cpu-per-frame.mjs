// The processor time one frame of the playground costs in headless Chromium on SwiftShader (all
// of the browser's processes: the page, the GPU process's software rasteriser, the compositor),
// with the page as most people see it and with reduced transparency (no backdrop blur behind the
// floating panels), interleaved, min / median / max over the rounds. This is what the browser
// tests pay per frame they wait for (docs/speed/suite.md); on a real GPU a frame is far cheaper.
//
//   BUILD_ONLY=1 ./scripts/serve.sh                # build www/
//   node benches/frame/cpu-per-frame.mjs [ROUNDS]  # default 4 rounds of 30 frames per look
import { execSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import { openPage, startPlayground, waitFrames } from '../../tests/e2e/lib.mjs';

const ROUNDS = Number(process.argv[2] ?? 4);
const FRAMES = 30;
const TICKS = Number(execSync('getconf CLK_TCK').toString());

/** CPU seconds (user + system) of process `root` and all its descendants. */
function treeCpu(root) {
  const rows = execSync('ps -e -o pid=,ppid=').toString().trim().split('\n').map((l) => l.trim().split(/\s+/));
  const children = new Map();
  for (const [pid, ppid] of rows) children.set(ppid, [...(children.get(ppid) ?? []), pid]);
  let ticks = 0;
  const stack = [String(root)];
  while (stack.length) {
    const pid = stack.pop();
    try {
      const fields = fs.readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
      ticks += Number(fields[11]) + Number(fields[12]);
    } catch {
      // The process ended in between.
    }
    stack.push(...(children.get(pid) ?? []));
  }
  return ticks / TICKS;
}

// The browser's main process: the one whose profile directory appeared with this launch.
const profiles = () => new Set(fs.readdirSync(os.tmpdir()).filter((d) => d.startsWith('playwright_chromiumdev_profile-')));
const before = profiles();
const play = await startPlayground({});
const mine = [...profiles()].filter((d) => !before.has(d));
if (mine.length !== 1) throw new Error(`cannot tell this browser's profile: ${mine.join(', ') || 'none'}`);
const browserPid = execSync(`pgrep -f -o -- '--user-data-dir=${os.tmpdir()}/${mine[0]}'`).toString().trim();

const looks = {};
for (const [name, defaultLook] of [['default look', true], ['reduced transparency', false]]) {
  const { page } = await openPage(play.context, play.url, 'webgpu', { defaultLook });
  await page.evaluate(() => window.screwbender.app.run('loadPreset', 'l_cycle_rotated'));
  await waitFrames(page, 5);
  looks[name] = { page, ms: [] };
}
for (let r = 0; r < ROUNDS; r++) {
  for (const look of Object.values(looks)) {
    await look.page.bringToFront();
    await waitFrames(look.page, 3);
    const start = treeCpu(browserPid);
    await waitFrames(look.page, FRAMES);
    look.ms.push(((treeCpu(browserPid) - start) / FRAMES) * 1000);
  }
}
console.log(`CPU: ${os.cpus()[0].model}, ${os.cpus().length} cores; load average ${os.loadavg()[0].toFixed(1)}`);
for (const [name, { ms }] of Object.entries(looks)) {
  const s = [...ms].sort((a, b) => a - b);
  console.log(`${name.padEnd(22)} ms of CPU per frame: min ${s[0].toFixed(0)} / median ${s[s.length >> 1].toFixed(0)} / max ${s[s.length - 1].toFixed(0)}`);
}
await play.close();
