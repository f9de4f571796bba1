// lessons.js REPO SITE_DIR: the lessons as a learner meets them from the index, in headless chromium.
// Serves SITE_DIR with web/serve.py (as ./ocean web does), opens the index, follows each chapter's
// "lesson" link, and from there every page of the lessons' site one link leads to, checking each:
// it is an HTML page (not Markdown text); a chapter's README page has the README's title as its
// heading and keeps its formulas' characters (the lessons write formulas as Unicode: Σ, ∂, ω...);
// every picture loaded (naturalWidth > 0); every link within the site answers 200, and a link to a
// #place finds it on the page; the console shows no error (a missing file shows there too).
// Exits 1 on the first page that fails any of these, listing what failed.
'use strict';
const { chromium } = require('playwright-core');
const { spawn } = require('child_process');
const fs = require('fs');
const path = require('path');

const [repo, site] = process.argv.slice(2);
if (!repo || !site) {
  console.error('usage: node lessons.js REPO SITE_DIR');
  process.exit(2);
}
const FORMULA_CHARACTERS = [...'Σ∂√ωπλ²ᵢ·×≈'];
const answers = new Map();  // address -> { status, body }: each file fetched once for all the pages

async function fetchOnce(request, address) {
  if (!answers.has(address)) {
    const answer = await request.get(address);
    answers.set(address, { status: answer.status(), body: answer.status() === 200 ? await answer.text() : '' });
  }
  return answers.get(address);
}

// web/serve.py on a free port: its first line names the address.
function serve() {
  const server = spawn('python3', [path.join(repo, 'web/serve.py'), repo, site, '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve, reject) => {
    server.on('exit', (code) => reject(new Error(`web/serve.py exited (${code})`)));
    server.stdout.on('data', (chunk) => {
      const found = /http:\/\/127\.0\.0\.1:\d+\//.exec(String(chunk));
      if (found) resolve({ server, root: found[0] });
    });
  });
}

// What is wrong with the page now open (null where nothing is): see the file's first lines.
async function problems(page, request, readme) {
  const found = [];
  const facts = await page.evaluate(() => ({
    contentType: document.contentType,
    heading: (document.querySelector('h1') || { textContent: '' }).textContent,
    text: document.body ? document.body.textContent : '',  // a closed <details> too
    pictures: [...document.images].map((i) => ({ src: i.src, loaded: i.complete && i.naturalWidth > 0 })),
    links: [...document.querySelectorAll('a[href]')].map((a) => a.href),
  }));
  if (facts.contentType !== 'text/html') return [`it is not an HTML page (${facts.contentType})`];
  if (readme) {
    const title = (/^#\s+(.*)$/m.exec(readme) || [null, ''])[1].replace(/`/g, '').trim();
    if (facts.heading.trim() !== title) found.push(`its heading is "${facts.heading.trim()}", the README's "${title}"`);
    for (const c of FORMULA_CHARACTERS)
      if (readme.includes(c) && !facts.text.includes(c)) found.push(`the README's formulas have ${c}, the page has none`);
  }
  for (const p of facts.pictures) if (!p.loaded) found.push(`the picture ${p.src} did not load`);
  const here = page.url().split('#')[0];
  const origin = new URL(here).origin;
  for (const link of new Set(facts.links.filter((l) => l.startsWith(origin)))) {
    const [address, place] = link.split('#');
    const answer = address === here ? null : await fetchOnce(request, address);
    if (answer && answer.status !== 200) { found.push(`the link ${link} answers ${answer.status}`); continue; }
    if (place === undefined || place === '') continue;
    const body = answer ? answer.body : await page.content();
    if (!body.includes(`id="${decodeURIComponent(place)}"`)) found.push(`the link ${link} finds no #${place} there`);
  }
  return found;
}

async function main() {
  const { server, root } = await serve();
  const browser = await chromium.launch({ executablePath: process.env.OCEAN_CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox'] });
  const failures = [];
  let checked = 0;
  try {
    const page = await browser.newPage();
    const consoleErrors = [];
    page.on('console', (m) => { if (m.type() === 'error') consoleErrors.push(m.text()); });
    await page.goto(root);
    const lessons = await page.$$eval('a', (as) => as.filter((a) => a.textContent === 'lesson').map((a) => a.href));
    const chapters = fs.readdirSync(repo).filter((d) => /^step\d\d_/.test(d) && fs.existsSync(path.join(repo, d, 'CMakeLists.txt')));
    if (lessons.length !== chapters.length) failures.push(`the index links ${lessons.length} lessons for ${chapters.length} chapters`);
    // Each chapter's lesson first, then every page of the site they lead to, once each.
    const queue = lessons.slice();
    const seen = new Set(queue);
    while (queue.length) {
      const address = queue.shift();
      const relative = decodeURIComponent(new URL(address).pathname).replace(/^\/lessons\//, '');
      const isReadme = lessons.includes(address);
      const readme = isReadme ? fs.readFileSync(path.join(repo, relative.replace(/\.html$/, '.md')), 'utf8') : null;
      consoleErrors.length = 0;
      const response = await page.goto(address);
      const found = response.status() === 200 ? await problems(page, page.request, readme) : [`it answers ${response.status()}`];
      for (const e of consoleErrors) found.push(`the console shows an error: ${e}`);
      for (const f of found) failures.push(`${relative}: ${f}`);
      checked++;
      if (found.length) continue;
      const next = await page.$$eval('a[href]', (as) => as.map((a) => a.href.split('#')[0]));
      for (const n of next)
        if (n.startsWith(root + 'lessons/') && n.endsWith('.html') && !seen.has(n)) { seen.add(n); queue.push(n); }
    }
  } finally {
    await browser.close();
    server.kill();
  }
  for (const f of failures) console.log('FAIL: ' + f);
  console.log(`lessons: ${checked} pages checked from ${root}, ${failures.length} problems`);
  process.exit(failures.length || checked === 0 ? 1 : 0);
}
main().catch((e) => { console.log('FAIL: ' + e.message); process.exit(1); });
