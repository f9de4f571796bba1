// render_lessons.mjs REPO SITE NODE_MODULES: the lessons as web pages, SITE/lessons/ (./ocean web).
//
// Every chapter's Markdown pages (its README and the pages beside it), and every Markdown page they
// link to, become HTML through marked (GitHub's flavour, pinned in tools/ocean_web.sh), at the path
// they have in the repository with .md turned to .html: so a relative link keeps its meaning, and
// only its suffix changes. What a page links to comes along: pictures copied as they are, other
// files (source, scripts) as a page showing their text (FILE.html), folders as their README's page.
// A link to nothing in the repository (links.py forbids them) becomes its words, with a warning:
// never a link to a missing page. The lessons write their formulas as Unicode text (Σ aᵢ sin(...)),
// mostly in indented blocks, so the pages need no math renderer and load nothing from the network.
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';

const [repoArg, siteArg, modules] = process.argv.slice(2);
if (!repoArg || !siteArg || !modules) {
  console.error('usage: node render_lessons.mjs REPO SITE NODE_MODULES');
  process.exit(2);
}
const repo = path.resolve(repoArg);
const out = path.join(path.resolve(siteArg), 'lessons');
// marked is an ES module; NODE_PATH does not reach an import, so it is found from NODE_MODULES.
const markedFile = createRequire(path.join(path.resolve(modules), 'noop.js')).resolve('marked');
const { Marked } = await import(pathToFileURL(markedFile).href);

const PICTURES = new Set(['.png', '.webp', '.svg', '.jpg', '.jpeg', '.gif']);
const chapters = fs.readdirSync(repo).filter((d) => /^step\d\d_/.test(d) && fs.existsSync(path.join(repo, d, 'CMakeLists.txt'))).sort();

const escapeHtml = (s) => s.replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
const inRepo = (file) => !path.relative(repo, file).startsWith('..') && !path.isAbsolute(path.relative(repo, file));

// GitHub's anchor for a heading (as tests/docs/links.py checks them): lower case, punctuation
// dropped, spaces to hyphens, a repeat numbered.
function slugger() {
  const seen = new Map();
  return (text) => {
    const base = text.toLowerCase().replace(/[^\p{L}\p{N}\p{M}_\- ]/gu, '').replace(/ /g, '-');
    const n = seen.get(base) || 0;
    seen.set(base, n + 1);
    return n ? `${base}-${n}` : base;
  };
}

const pending = [];  // repository-relative files still to put on the site
const done = new Set();
const warnings = [];
function want(relative) {
  if (!done.has(relative)) { done.add(relative); pending.push(relative); }
}

// Where a link of the page `from` (repository-relative) leads on the site, relative to that page;
// null where it leads to nothing the site can hold.
function siteHref(from, href) {
  if (/^([a-z]+:|#)/i.test(href)) return href;  // a web address or a place on the same page
  const [target, fragment] = href.split('#', 2);
  let decoded;
  try {
    decoded = decodeURIComponent(target);
  } catch {  // a stray % in the address
    return null;
  }
  let file = path.resolve(repo, path.dirname(from), decoded);
  if (!inRepo(file) || !fs.existsSync(file)) return null;
  if (fs.statSync(file).isDirectory()) {
    file = path.join(file, 'README.md');
    if (!fs.existsSync(file)) return null;
  }
  const relative = path.relative(repo, file);
  want(relative);
  const ext = path.extname(file).toLowerCase();
  const onSite = ext === '.md' ? relative.slice(0, -3) + '.html' : PICTURES.has(ext) ? relative : relative + '.html';
  const link = path.relative(path.dirname(from), onSite).split(path.sep).join('/');
  return fragment === undefined ? link : `${link}#${fragment}`;
}

function page(title, from, body) {
  const index = path.relative(path.dirname(path.join('lessons', from)), 'index.html').split(path.sep).join('/');
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>${escapeHtml(title)} · Sin waves into water</title>
<style>
  body { margin: 2em auto; max-width: 52em; padding: 0 1em; background: #111418; color: #c8d0d8; font: 15px/1.55 sans-serif; }
  a { color: #7fb8ff; }
  img { max-width: 100%; }
  pre, code { font: 13px/1.45 monospace; background: #1b2027; }
  pre { padding: 0.6em 0.8em; overflow-x: auto; }
  pre code { background: none; }
  table { border-collapse: collapse; }
  th, td { padding: 0.3em 0.6em; border: 1px solid #2a3038; vertical-align: top; }
  nav { font-size: 0.9em; opacity: 0.8; }
</style>
</head>
<body>
<nav><a href="${index}">all chapters</a> · ${escapeHtml(from)}</nav>
<main>
${body}</main>
</body>
</html>
`;
}

function renderMarkdown(from) {
  const slug = slugger();
  const marked = new Marked({
    gfm: true,
    walkTokens(token) {
      if (token.type === 'link' || token.type === 'image') {
        const href = siteHref(from, token.href);
        if (href === null) {
          warnings.push(`${from}: ${token.href} leads to nothing in the repository: left as text`);
          token.unlinked = true;
        } else {
          token.href = href;
        }
      } else if (token.type === 'html') {  // a table's sized thumbnail: <img src="..." width="192">
        token.text = token.text.replace(/(<img\s[^>]*src=")([^"]+)"/g, (all, before, src) => {
          const href = siteHref(from, src);
          return href === null ? all : `${before}${href}"`;
        });
      }
    },
    renderer: {
      link(token) { return token.unlinked ? this.parser.parseInline(token.tokens) : false; },
      image(token) { return token.unlinked ? escapeHtml(token.text) : false; },
      heading(token) {
        return `<h${token.depth} id="${slug(token.text)}">${this.parser.parseInline(token.tokens)}</h${token.depth}>\n`;
      },
    },
  });
  const text = fs.readFileSync(path.join(repo, from), 'utf8');
  const title = (text.match(/^#\s+(.*)$/m) || [null, from])[1].replace(/`/g, '');
  return page(title, from, marked.parse(text));
}

function write(relative, content) {
  const file = path.join(out, relative);
  fs.mkdirSync(path.dirname(file), { recursive: true });
  fs.writeFileSync(file, content);
}

for (const chapter of chapters)
  for (const name of fs.readdirSync(path.join(repo, chapter)).filter((n) => n.endsWith('.md')).sort())
    want(path.join(chapter, name));
let counts = { pages: 0, pictures: 0, files: 0 };
while (pending.length) {
  const relative = pending.shift();
  const ext = path.extname(relative).toLowerCase();
  if (ext === '.md') {
    write(relative.slice(0, -3) + '.html', renderMarkdown(relative));
    counts.pages++;
  } else if (PICTURES.has(ext)) {
    write(relative, fs.readFileSync(path.join(repo, relative)));
    counts.pictures++;
  } else {  // a source file, a script: its text, on a page of its own
    const text = fs.readFileSync(path.join(repo, relative), 'utf8');
    write(relative + '.html', page(relative, relative, `<h1>${escapeHtml(relative)}</h1>\n<pre>${escapeHtml(text)}</pre>\n`));
    counts.files++;
  }
}
for (const w of warnings) console.error(`render_lessons.mjs: warning: ${w}`);
console.log(`render_lessons.mjs: ${out}: ${counts.pages} pages, ${counts.pictures} pictures, ${counts.files} files shown as text`);
