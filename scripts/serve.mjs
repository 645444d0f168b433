#!/usr/bin/env node
// Tiny static file server for the playground (node builtins only).
//
//   node scripts/serve.mjs [DIR]      # DIR defaults to www; PORT env (default 8080)
//
// Why not `python3 -m http.server`: it sends no Cache-Control, so after a rebuild a reload may
// run stale wasm/JS. Here every response is `Cache-Control: no-store`, and .wasm is served as
// application/wasm (WebAssembly.instantiateStreaming refuses anything else).
// Listens on 127.0.0.1 only. Without PORT, a busy 8080 moves on to the next free port.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';

const HOST = '127.0.0.1';
const root = path.resolve(process.argv[2] ?? 'www');
const explicitPort = process.env.PORT !== undefined && process.env.PORT !== '';
let port = explicitPort ? Number(process.env.PORT) : 8080;
const MAX_PORT_TRIES = 20;

const MIME = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.gif': 'image/gif',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.webp': 'image/webp',
  '.glb': 'model/gltf-binary',
  '.gltf': 'model/gltf+json',
  '.bin': 'application/octet-stream',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
  '.wgsl': 'text/plain; charset=utf-8',
  '.csv': 'text/csv; charset=utf-8',
  '.d.ts': 'text/plain; charset=utf-8',
};

// Any origin may read the files (as static hosts such as GitHub Pages allow): embed.html in a
// `sandbox="allow-scripts"` iframe runs in an opaque origin, for which its own modules and wasm
// are cross-origin requests.
const COMMON_HEADERS = { 'Cache-Control': 'no-store', 'X-Content-Type-Options': 'nosniff', 'Access-Control-Allow-Origin': '*' };

function send(res, status, body, headers = {}) {
  res.writeHead(status, { ...COMMON_HEADERS, 'Content-Type': 'text/plain; charset=utf-8', ...headers });
  res.end(body);
}

function escapeHtml(s) {
  return s.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);
}

async function listing(res, dir, urlPath) {
  const entries = await fs.promises.readdir(dir, { withFileTypes: true });
  const items = entries
    .map((e) => e.name + (e.isDirectory() ? '/' : ''))
    .sort()
    .map((n) => `<li><a href="${encodeURI(n)}">${escapeHtml(n)}</a></li>`)
    .join('\n');
  send(res, 200, `<!doctype html><title>${escapeHtml(urlPath)}</title><ul>\n${items}\n</ul>\n`, {
    'Content-Type': 'text/html; charset=utf-8',
  });
}

async function handle(req, res) {
  if (req.method !== 'GET' && req.method !== 'HEAD') {
    return send(res, 405, 'method not allowed\n', { Allow: 'GET, HEAD' });
  }
  let urlPath;
  try {
    urlPath = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
  } catch {
    return send(res, 400, 'bad request\n');
  }
  // path.join normalises `..`; anything that lands outside root is refused.
  let file = path.join(root, urlPath);
  if (file !== root && !file.startsWith(root + path.sep)) return send(res, 403, 'forbidden\n');

  let stat = await fs.promises.stat(file).catch(() => null);
  if (stat?.isDirectory()) {
    if (!urlPath.endsWith('/')) return send(res, 301, '', { Location: `${urlPath}/` });
    const index = path.join(file, 'index.html');
    const indexStat = await fs.promises.stat(index).catch(() => null);
    if (!indexStat?.isFile()) return listing(res, file, urlPath);
    file = index;
    stat = indexStat;
  }
  if (!stat?.isFile()) return send(res, 404, 'not found\n');

  const base = path.basename(file).toLowerCase();
  const ext = base.endsWith('.d.ts') ? '.d.ts' : path.extname(base);
  res.writeHead(200, {
    ...COMMON_HEADERS,
    'Content-Type': MIME[ext] ?? 'application/octet-stream',
    'Content-Length': stat.size,
  });
  if (req.method === 'HEAD') return res.end();
  fs.createReadStream(file)
    .on('error', () => res.destroy())
    .pipe(res);
}

const server = http.createServer((req, res) => {
  handle(req, res)
    .catch((err) => {
      console.error(err);
      if (!res.headersSent) send(res, 500, 'internal error\n');
      else res.destroy();
    })
    .finally(() => {
      if (process.env.SERVE_QUIET !== '1') console.log(`${req.method} ${req.url} ${res.statusCode}`);
    });
});

let tries = 0;
server.on('error', (err) => {
  if (err.code === 'EADDRINUSE' && !explicitPort && ++tries < MAX_PORT_TRIES) {
    port += 1;
    server.listen(port, HOST);
    return;
  }
  console.error(`serve.mjs: cannot listen on ${HOST}:${port}: ${err.message}`);
  process.exit(1);
});
server.on('listening', () => {
  console.log(`Serving ScrewBender playground at http://${HOST}:${server.address().port}/`);
  console.log(`(files from ${root}; Ctrl-C stops)`);
});

if (!fs.existsSync(root)) {
  console.error(`serve.mjs: no such directory: ${root}`);
  process.exit(1);
}
server.listen(port, HOST);
