// page.js SITE_DIR STEP OUT_DIR NAME [--query=Q] [PROGRAM ARGUMENTS...]
// Opens SITE_DIR/STEP.html in headless chromium (WebGL 2 through SwiftShader) with the program's
// arguments in the address (each as ?arg=, after Q as a user would type it: name=value&...), waits for the program to exit, and writes what a test
// reads: OUT_DIR/NAME.log (the console and the exit status) and, when the arguments hold
// `--screenshot FILE`, OUT_DIR/NAME.png (the file the program wrote in the page's file system).
// Exits 1 when the page logs an error, throws, exits non-zero or does not exit within the limit.
// Needs playwright-core (./ocean web installs it into build/web/node_modules) and /usr/bin/chromium.
'use strict';
const { chromium } = require('playwright-core');
const fs = require('fs');
const http = require('http');
const path = require('path');

const [site, step, outDir, name, ...rest] = process.argv.slice(2);
const userQuery = rest.length && rest[0].startsWith('--query=') ? rest.shift().slice('--query='.length) : '';
const programArgs = rest;
if (!site || !step || !outDir || !name) {
  console.error('usage: node page.js SITE_DIR STEP OUT_DIR NAME [--query=Q] [PROGRAM ARGUMENTS...]');
  process.exit(2);
}
const limitMs = Number(process.env.OCEAN_WEB_TIMEOUT_MS || 120000);
const shotIndex = programArgs.indexOf('--screenshot');
const shotInPage = shotIndex >= 0 ? programArgs[shotIndex + 1] : null;

// The pages, served from SITE_DIR as a web server would (a page loads its .wasm and .data by address).
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm' };
const server = http.createServer((request, response) => {
  let file;
  try {
    file = path.join(site, path.normalize(decodeURIComponent(request.url.split('?')[0])));
  } catch (e) {
    response.writeHead(400); response.end(); return;
  }
  fs.readFile(file, (error, data) => {
    if (error) { response.writeHead(404); response.end(); return; }
    response.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
    response.end(data);
  });
});

async function main() {
  await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
  const parts = (userQuery ? [userQuery] : []).concat(programArgs.map((a) => 'arg=' + encodeURIComponent(a)));
  const query = parts.length ? '?' + parts.join('&') : '';
  const address = `http://127.0.0.1:${server.address().port}/${step}.html${query}`;
  const browser = await chromium.launch({
    executablePath: process.env.OCEAN_CHROMIUM || '/usr/bin/chromium',
    args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--no-sandbox'],
  });
  const log = [];
  const problems = [];
  try {
    const page = await browser.newPage({ viewport: { width: 1024, height: 640 } });
    page.on('console', (m) => {
      log.push(`${m.type()}: ${m.text()}`);
      if (m.type() === 'error') problems.push(`the console shows an error: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`the page threw: ${e.message}`));
    log.push(`open ${address}`);
    const started = Date.now();
    await page.goto(address);
    await page.waitForFunction(() => window.oceanExitStatus !== undefined, null, { timeout: limitMs, polling: 200 })
      .catch(() => problems.push(`the program did not exit within ${limitMs / 1000} s`));
    const status = await page.evaluate(() => window.oceanExitStatus);
    log.push(`exit status ${status} after ${((Date.now() - started) / 1000).toFixed(1)} s`);
    if (status !== undefined && status !== 0) problems.push(`the program exited with status ${status}`);
    if (shotInPage && status === 0) {
      const bytes = await page.evaluate((file) => Array.from(Module.FS.readFile(file)), shotInPage)
        .catch((e) => { problems.push(`no screenshot at ${shotInPage} in the page: ${e.message}`); return null; });
      if (bytes) fs.writeFileSync(path.join(outDir, name + '.png'), Buffer.from(bytes));
    }
  } finally {
    await browser.close();
    server.close();
  }
  fs.writeFileSync(path.join(outDir, name + '.log'), log.concat(problems.map((p) => 'FAIL: ' + p)).join('\n') + '\n');
  console.log(log.join('\n'));
  for (const p of problems) console.log('FAIL: ' + p);
  process.exit(problems.length ? 1 : 0);
}
main().catch((e) => { console.log('FAIL: ' + e.message); process.exit(1); });
