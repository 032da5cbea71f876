// site_test.js: the book in a real browser (make site-test). Debian's
// chromium, driven by playwright-core, opens every page of build/site served
// on 127.0.0.1, and checks:
//   - it loads with no console error, no script error and no failed request;
//   - every picture on it is drawn (complete, with a width);
//   - every link into the site reaches a file, and its #fragment an id there;
//   - each page of the book in reading order links the one before and after;
//   - the search finds each book page from words of one of its headings;
//   - the theme button turns dark to light and back, and a reload keeps it.
// Prints one line per failure, then "site-test: N passed, M failed".
//
//   node tools/site/test/site_test.js SITE_DIR NODE_MODULES
"use strict";
const fs = require("fs");
const path = require("path");
const {serve} = require("../serve.js");

const site = path.resolve(process.argv[2] || "build/site");
const modules = path.resolve(process.argv[3] || "build/site-node/node_modules");
const {chromium} = require(path.join(modules, "playwright-core"));

let passed = 0, failed = 0;
function check(ok, what) {
  if (ok) passed++;
  else { failed++; console.log("FAIL: " + what); }
}

function htmlFiles(dir) {
  const out = [];
  for (const e of fs.readdirSync(dir, {withFileTypes: true})) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) out.push(...htmlFiles(p));
    else if (e.name.endsWith(".html")) out.push(path.relative(site, p));
  }
  return out.sort();
}

// A link into the site: the file it names (a directory: its index.html).
function fileOf(url) {
  let f = path.join(site, decodeURIComponent(url.pathname));
  if (fs.existsSync(f) && fs.statSync(f).isDirectory()) f = path.join(f, "index.html");
  return f;
}

const idCache = new Map();
function hasId(file, id) {
  if (!idCache.has(file)) {
    const ids = new Set();
    for (const m of fs.readFileSync(file, "utf8").matchAll(/\sid="([^"]*)"/g)) ids.add(m[1]);
    idCache.set(file, ids);
  }
  return idCache.get(file).has(id);
}

async function main() {
  const server = await new Promise((resolve) => serve(site, 0, (s, port) => resolve({s, port})));
  const base = `http://127.0.0.1:${server.port}/`;
  const browser = await chromium.launch({
    executablePath: "/usr/bin/chromium",
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync"],
  });
  const page = await browser.newPage({viewport: {width: 1400, height: 1000}});
  let problems = [];
  page.on("console", (m) => { if (m.type() === "error") problems.push("console: " + m.text()); });
  page.on("pageerror", (e) => problems.push("script error: " + e.message));
  page.on("requestfailed", (r) => problems.push("request failed: " + r.url()));
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });

  const pages = htmlFiles(site);
  let links = 0, images = 0;
  for (const p of pages) {
    problems = [];
    await page.goto(base + p, {waitUntil: "load"});
    for (const e of problems) check(false, `${p}: ${e}`);
    check(problems.length === 0, `${p} loads cleanly`);
    const imgs = await page.$$eval("img", (list) => list.map((i) => ({
      src: i.getAttribute("src"), ok: i.complete && i.naturalWidth > 0})));
    for (const i of imgs) { images++; check(i.ok, `${p}: picture ${i.src} is not drawn`); }
    const hrefs = await page.$$eval("a[href]", (list) => list.map((a) => a.href));
    for (const h of new Set(hrefs)) {
      const url = new URL(h);
      if (!url.href.startsWith(base)) {
        check(/^(https?|mailto):$/.test(url.protocol), `${p}: link ${h} leaves the site oddly`);
        continue;
      }
      links++;
      const file = fileOf(url);
      if (!fs.existsSync(file)) { check(false, `${p}: link ${h} reaches no file`); continue; }
      const id = decodeURIComponent(url.hash.slice(1));
      if (id && file.endsWith(".html")) check(hasId(file, id), `${p}: link ${h}: no id "${id}" there`);
      else check(true, "");
    }
  }

  // The book in reading order, from the sidebar of its first page.
  await page.goto(base + "index.html");
  const book = await page.$$eval(".sidebar a", (list) => list.map((a) => a.getAttribute("data-page")));
  check(book.length >= 15, `the sidebar lists ${book.length} pages, fewer than 15`);
  for (let k = 0; k < book.length; k++) {
    await page.goto(base + book[k]);
    const prev = await page.$eval(".prevnext", (n) => {
      const a = n.querySelector(".prev"); return a ? a.href : null; });
    const next = await page.$eval(".prevnext", (n) => {
      const a = n.querySelector(".next"); return a ? a.href : null; });
    check(k === 0 ? prev === null : prev === base + book[k - 1], `${book[k]}: previous page`);
    check(k === book.length - 1 ? next === null : next === base + book[k + 1], `${book[k]}: next page`);
    // Search: the words of the page's second heading (its first section).
    const heading = await page.$$eval("article h2", (hs) => hs.length ? hs[0].textContent : null);
    if (!heading) continue;
    const words = heading.replace(/[^\p{L}\p{N}\s-]/gu, " ").split(/\s+/).filter((w) => w.length > 3).slice(0, 3).join(" ");
    await page.fill("#search", words);
    const found = await page.$$eval("#results a", (list) => list.map((a) => a.href.split("#")[0]));
    check(found.includes(base + book[k]), `search "${words}" does not find ${book[k]}`);
    await page.fill("#search", "");
  }

  // The theme: a click turns it, a reload keeps it, a second click turns it back.
  await page.goto(base + "docs/02_zbuffer.html");
  const before = await page.getAttribute("html", "data-theme");
  await page.click("#theme");
  const after = await page.getAttribute("html", "data-theme");
  check(before !== after && ["light", "dark"].includes(after), `the theme button turns ${before} to ${after}`);
  await page.reload();
  check(await page.getAttribute("html", "data-theme") === after, "a reload keeps the theme");
  await page.click("#theme");
  check(await page.getAttribute("html", "data-theme") === before, "a second click turns it back");

  await browser.close();
  server.s.close();
  console.log(`site-test: ${pages.length} pages, ${links} links into the site, ${images} pictures`);
  console.log(`site-test: ${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => { console.log("site-test: " + (e && e.stack || e)); process.exit(1); });
