// site_test.js: the book in a real browser (make site-test). Debian's
// chromium, driven by playwright-core, opens every page of build/site served
// on 127.0.0.1, and checks:
//   - it loads with no console error, no script error and no failed request;
//   - every picture on it is drawn (complete, with a width);
//   - every link into the site reaches a file, and its #fragment an id there;
//     and every file of a lesson the book holds is linked from a page, and
//     from wherever a page names it in code;
//   - each page of the book in reading order links the one before and after;
//   - the search finds each book page from words of one of its headings;
//   - book.pdf and book.epub hold every page of the book, by its title, and
//     nothing of the printed book is wider than its page;
//   - "/" goes to the search, but not from a Run command line, which takes it;
//   - a page opened as a file, where no lesson can run, says so at Run;
//   - the theme button turns dark to light and back, and a reload keeps it;
//   - every Run button of a page, pressed in the page's order, runs the
//     lesson in the page as the native one runs in a directory of its own
//     (the tree's docs/examples/ and tests/expected/, then what the page's
//     earlier commands wrote): the same status, stdout and stderr, and the
//     same files, byte for byte, and none reads a file not there; lesson
//     10 natively on one thread with plain C blocks, as in the page, and
//     refused in one line there when asked for more;
//   - every live figure responds: a steps figure draws its steps, its slider
//     turns the picture, and a pixel clicked shows what the native --trace
//     prints for it; a flags figure, at first and after each choice turned,
//     shows a picture and the summary the native lesson prints for the same
//     arguments.
// Prints one line per failure, then "site-test: N passed, M failed".
//
//   node tools/site/test/site_test.js SITE_DIR NODE_MODULES BIN_DIR WORK_DIR
"use strict";
const fs = require("fs");
const path = require("path");
const {spawnSync} = require("child_process");
const {serve} = require("../serve.js");
const crypto = require("crypto");
const {notInTheBrowser} = require("./not_in_the_browser.js");

const site = path.resolve(process.argv[2] || "build/site");
const modules = path.resolve(process.argv[3] || "build/site-node/node_modules");
const bin = path.resolve(process.argv[4] || "build/bin");
const work = path.resolve(process.argv[5] || "build/test-output/site");
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

// A file as the comparison sees it: its bytes, as a SHA-256 in hex
// (inPageResult does the same in the page). The browser build's PNGs are
// the native ones byte for byte: its deflate is pako's, zlib's bytes.
function digestOf(name, bytes) {
  return crypto.createHash("sha256").update(bytes).digest("hex");
}

// In the page: a Run widget's result, its files as digestOf gives them.
async function inPageResult(el) {
  const r = el.result;
  if (!r) return null;
  if (r.error) return {error: r.error};
  const hex = (d) => Array.from(new Uint8Array(d), (b) => b.toString(16).padStart(2, "0")).join("");
  const written = [];
  for (const [name, bytes] of r.written)
    written.push([name, hex(await crypto.subtle.digest("SHA-256", bytes))]);
  return {status: r.status, stdout: r.stdout, stderr: r.stderr, written};
}

// Every file under dir, by path relative to it.
function snapshot(dir, rel = "", out = new Map()) {
  for (const e of fs.readdirSync(path.join(dir, rel), {withFileTypes: true})) {
    const r = rel ? rel + "/" + e.name : e.name;
    if (e.isDirectory()) snapshot(dir, r, out);
    else out.set(r, fs.readFileSync(path.join(dir, r)));
  }
  return out;
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
  page.on("console", (m) => {
    if (m.type() === "error") problems.push(`console: ${m.text()} (${m.location().url})`);
  });
  page.on("pageerror", (e) => problems.push("script error: " + e.message));
  page.on("requestfailed", (r) => problems.push("request failed: " + r.url()));
  page.on("response", (r) => { if (r.status() >= 400) problems.push(`${r.status()}: ${r.url()}`); });

  const pages = htmlFiles(site);
  let links = 0, images = 0;
  const reached = new Set(); // every file a link of a page reaches
  for (const p of pages) {
    problems = [];
    await page.goto(base + p, {waitUntil: "load"});
    for (const e of problems) check(false, `${p}: ${e}`);
    check(problems.length === 0, `${p} loads cleanly`);
    const imgs = await page.$$eval("img", (list) => list.map((i) => ({
      src: i.getAttribute("src"), ok: i.complete && i.naturalWidth > 0,
      width: Number(i.getAttribute("width")), shown: i.getBoundingClientRect().width})));
    for (const i of imgs) {
      images++;
      check(i.ok, `${p}: picture ${i.src} is not drawn`);
      // A picture given its width (a thumbnail) is drawn that wide.
      if (i.width) check(Math.abs(i.shown - i.width) < 1, `${p}: picture ${i.src} is ${i.shown} px wide, not ${i.width}`);
    }
    // A file of the tree the book holds, named in code, opens from there.
    const named = await page.$$eval("article code", (list) => list.filter((c) => !c.closest("a, pre"))
      .map((c) => c.textContent).filter((t) => /^(lessons\/\d\d_\w+\/[\w/]*|common\/[\w/]*)\.[ch]$/.test(t)));
    for (const f of new Set(named))
      check(!fs.existsSync(path.join(site, f)), `${p}: \`${f}\` is not a link to the file the book holds`);
    const hrefs = await page.$$eval("a[href]", (list) => list.map((a) => a.href));
    for (const h of new Set(hrefs)) {
      const url = new URL(h);
      if (!url.href.startsWith(base)) {
        check(/^(https?|mailto):$/.test(url.protocol), `${p}: link ${h} leaves the site oddly`);
        continue;
      }
      links++;
      const file = fileOf(url);
      reached.add(file);
      if (!fs.existsSync(file)) { check(false, `${p}: link ${h} reaches no file`); continue; }
      const id = decodeURIComponent(url.hash.slice(1));
      if (id && file.endsWith(".html")) check(hasId(file, id), `${p}: link ${h}: no id "${id}" there`);
      else check(true, "");
    }
  }

  // Every file of a lesson that the book holds is linked from a page: a
  // browser lists no directory, and a file no page links to is lost.
  (function lessonFiles(dir) {
    for (const e of fs.readdirSync(dir, {withFileTypes: true})) {
      const f = path.join(dir, e.name);
      if (e.isDirectory()) lessonFiles(f);
      else if (/\.[ch]$/.test(e.name)) check(reached.has(f), `${path.relative(site, f)}: no page links to it`);
    }
  })(path.join(site, "lessons"));

  // The book in reading order, from the sidebar of its first page.
  await page.goto(base + "index.html");
  const book = await page.$$eval(".sidebar a[data-page]", (list) => list.map((a) => a.getAttribute("data-page")));
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

  // The whole book, as PDF and EPUB: every page of the book is in each, by
  // its title (pdftotext and pandoc read them back), and the PDF has pages.
  const titles = [];
  for (const p of book) {
    await page.goto(base + p);
    titles.push(await page.$eval("article h1", (h) => h.textContent));
  }
  const flat = (t) => t.replace(/\s+/g, " ");
  const pdf = spawnSync("pdftotext", [path.join(site, "book.pdf"), "-"], {encoding: "utf8"});
  const pdfPages = Number((spawnSync("pdfinfo", [path.join(site, "book.pdf")], {encoding: "utf8"})
                               .stdout.match(/Pages:\s+(\d+)/) || [0, 0])[1]);
  const epub = spawnSync("pandoc", ["--from", "epub", "--to", "plain", path.join(site, "book.epub")],
                         {encoding: "utf8"});
  check(pdf.status === 0 && epub.status === 0, "pdftotext and pandoc read book.pdf and book.epub");
  check(pdfPages >= book.length, `book.pdf has ${pdfPages} pages for ${book.length} pages of the book`);
  for (const t of titles) {
    check(flat(pdf.stdout || "").includes(flat(t)), `book.pdf lacks the page "${t}"`);
    check(flat(epub.stdout || "").includes(flat(t)), `book.epub lacks the page "${t}"`);
  }
  // Nothing of the printed book is wider than its column on a Letter page
  // (816 px): chromium would shrink every page of book.pdf to fit it, and
  // still cut off what is beyond the edge (a wide table's last column); and
  // a picture given its width (a thumbnail) is printed that wide.
  const print = await browser.newPage({viewport: {width: 816, height: 1056}});
  await print.goto(base + "book-print.html");
  await print.emulateMedia({media: "print"});
  const wide = await print.evaluate(() => {
    // (A space that ends a line of inline code hangs past it: less than 8 px.)
    const right = document.body.getBoundingClientRect().right + 8;
    return Array.from(document.querySelectorAll("body *"))
      .filter((e) => e.getBoundingClientRect().right > right && !e.closest("nav"))
      .map((e) => "wider than the page: " + e.tagName + ": " +
                  e.textContent.replace(/\s+/g, " ").trim().slice(0, 60))
      .concat(Array.from(document.querySelectorAll("img[width]"))
        .filter((i) => Math.abs(i.getBoundingClientRect().width - Number(i.getAttribute("width"))) >= 1)
        .map((i) => `picture ${i.getAttribute("src")} is ${i.getBoundingClientRect().width} px wide, ` +
                    `not ${i.getAttribute("width")}`));
  });
  for (const w of wide.slice(0, 10)) check(false, `book.pdf: ${w}`);
  check(wide.length === 0, `book.pdf: ${wide.length} elements wider than the page or squeezed`);
  await print.close();

  // "/" goes to the search from the page, but is typed as itself into a
  // Run command line.
  await page.goto(base + "docs/02_zbuffer.html");
  await page.keyboard.press("/");
  check(await page.evaluate(() => document.activeElement.id) === "search", "\"/\" does not go to the search");
  const cmdLine = await page.$(".run-cmd");
  const typed = (await cmdLine.evaluate((i) => i.value)) + " --out out/mine.png";
  await cmdLine.click();
  await page.keyboard.press("End");
  await page.keyboard.type(" --out out/mine.png");
  check(await cmdLine.evaluate((i) => i.value) === typed,
        `a Run command line typed into reads "${await cmdLine.evaluate((i) => i.value)}"`);

  // A page opened as a file cannot start the worker: Run says so, and how
  // to read the book instead, rather than "running" for ever.
  const asFile = await browser.newPage();
  await asFile.goto("file://" + path.join(site, "docs/02_zbuffer.html"));
  const fileRun = await asFile.$(".run");
  await fileRun.$eval(".run-button", (b) => b.click());
  const said = await asFile.waitForFunction((el) => el.getAttribute("data-state") === "done", fileRun,
                                            {timeout: 10000})
    .then(() => fileRun.$eval(".run-out", (o) => o.textContent), () => "(still running)");
  check(/make site-serve/.test(said), `a page opened as a file says, at Run: ${said}`);
  await asFile.close();

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

  // Run it here, page by page, each command after the one before it.
  let runs = 0;
  for (const p of book) {
    await page.goto(base + p);
    const widgets = await page.$$(".run");
    if (!widgets.length) continue;
    const dir = path.join(work, p.replace(/[/.]/g, "_"));
    fs.rmSync(dir, {recursive: true, force: true});
    fs.mkdirSync(dir, {recursive: true});
    // The files of the tree a page's command may read: its examples and
    // the expected pictures (--compare tests/expected/...).
    for (const d of ["docs/examples", "tests/expected"])
      fs.cpSync(path.resolve(d), path.join(dir, d), {recursive: true});
    for (const w of widgets) {
      const cmd = await w.$eval(".run-cmd", (i) => i.value);
      const [program, ...args] = cmd.split(/\s+/);
      await w.$eval(".run-button", (b) => b.click());
      await page.waitForFunction((el) => el.getAttribute("data-state") === "done", w, {timeout: 120000});
      const r = await w.evaluate(inPageResult);
      runs++;
      const label = `${p}: Run ${cmd}`;
      if (!r || r.error) { check(false, `${label}: ${r ? r.error : "no result"}`); continue; }
      // A Run button whose command cannot run in the page, since a file it
      // reads is not there, is a button that does nothing.
      check(!/No such file or directory/.test(r.stderr), `${label}: reads a file not in the page:\n${r.stderr}`);
      if (notInTheBrowser(args)) {
        check(r.status === 2 && r.stderr.split("\n").filter(Boolean).length === 1 && !r.stdout,
              `${label}: should be refused in the page in one line (status ${r.status})`);
        continue;
      }
      const before = snapshot(dir);
      const as = program.endsWith("10_fast_raster") ? ["--threads", "1", "--simd", "none"] : [];
      const native = spawnSync(path.join(bin, path.basename(program)), [...args, ...as],
                               {cwd: dir, encoding: "utf8"});
      check(r.status === native.status, `${label}: status ${r.status} in the page, ${native.status} natively`);
      check(r.stdout === native.stdout, `${label}: prints\n${r.stdout}natively:\n${native.stdout}`);
      check(r.stderr === native.stderr, `${label}: says\n${r.stderr}natively:\n${native.stderr}`);
      const after = snapshot(dir), wrote = [...after.keys()].filter((f) =>
        !before.has(f) || Buffer.compare(before.get(f), after.get(f)) !== 0).sort();
      const inPage = new Map(r.written);
      check([...inPage.keys()].sort().join() === wrote.join(),
            `${label}: writes ${[...inPage.keys()]} in the page, ${wrote} natively`);
      for (const f of wrote)
        if (inPage.has(f)) check(digestOf(f, after.get(f)) === inPage.get(f), `${label}: ${f} differs`);
    }
  }
  check(runs >= 80, `only ${runs} Run buttons on the pages`);

  // Every live figure responds: drawn face by face, the slider turns the
  // picture, and a pixel clicked gets what the native --trace prints for it.
  let figures = 0;
  for (const p of book) {
    await page.goto(base + p);
    for (const f of await page.$$('.figure-live[data-kind="flags"]')) {
      figures++;
      const lesson = await f.getAttribute("data-lesson");
      await f.$eval(".figure-start", (b) => b.click());
      const selects = await f.$$("select");
      check(selects.length >= 1, `${p}: figure of ${lesson} offers no choice`);
      // Its first run, then each choice turned to its last value in turn.
      for (let k = 0; k <= selects.length; k++) {
        if (k > 0)
          await selects[k - 1].evaluate((sel) => {
            sel.value = sel.options[sel.options.length - 1].value;
            sel.dispatchEvent(new Event("change"));
          });
        await page.waitForFunction(([el, n]) => el.getAttribute("data-runs") === String(n),
                                   [f, k + 1], {timeout: 120000});
        const args = (await f.getAttribute("data-run")).split(" ");
        const shown = await f.$eval(".figure-trace", (t) => t.textContent);
        // The run is counted as its picture's src is set: wait for it to load.
        const drawn = await page.waitForFunction((el) => {
          const i = el.querySelector(".figure-picture");
          return i && i.complete && i.naturalWidth > 0 && i.currentSrc === i.src;
        }, f, {timeout: 30000}).then(() => true, () => false);
        const dir = path.join(work, "figure-flags");
        fs.rmSync(dir, {recursive: true, force: true});
        fs.mkdirSync(dir, {recursive: true});
        const native = spawnSync(path.join(bin, lesson), args, {cwd: dir, encoding: "utf8"});
        check(drawn, `${p}: figure of ${lesson} ${args.join(" ")}: no picture`);
        check(shown === native.stdout + native.stderr,
              `${p}: figure of ${lesson} ${args.join(" ")} shows\n${shown}\nnatively:\n${native.stdout}${native.stderr}`);
      }
    }
    for (const f of await page.$$('.figure-live[data-kind="steps"]')) {
      figures++;
      const lesson = await f.getAttribute("data-lesson");
      const extra = (await f.getAttribute("data-args") || "").split(/\s+/).filter(Boolean);
      await f.$eval(".figure-start", (b) => b.click());
      await page.waitForFunction((el) => el.getAttribute("data-state") === "ready", f, {timeout: 120000});
      const steps = Number(await f.$eval(".figure-slider", (r) => r.max));
      check(steps >= 2, `${p}: figure of ${lesson}: ${steps + 1} pictures, not one per face and the clear`);
      const last = await f.$eval(".figure-picture", (i) => i.src);
      await f.$eval(".figure-slider", (r) => { r.value = "0"; r.dispatchEvent(new Event("input")); });
      check(await f.$eval(".figure-picture", (i) => i.src) !== last, `${p}: the slider does not turn the picture`);
      const [x, y] = [160, 150];
      const img = await f.$(".figure-picture");
      const box = await img.boundingBox();
      await img.click({position: {x: (x + 0.5) * box.width / 320, y: (y + 0.5) * box.height / 240}});
      await page.waitForFunction((el) => el.getAttribute("data-state") === "traced", f, {timeout: 120000});
      const shown = await f.$eval(".figure-trace", (t) => t.textContent);
      const native = spawnSync(path.join(bin, lesson), ["--width", "320", "--height", "240", ...extra,
                                "--trace", `${x},${y}`, "--out", path.join(work, "figure.png")],
                               {encoding: "utf8"}).stdout;
      const at = native.search(/^(trace pixel|no fragment)/m);
      check(at >= 0 && shown === native.slice(at),
            `${p}: figure's trace of (${x},${y}) is\n${shown}\nnatively:\n${native.slice(at)}`);
    }
  }
  check(figures >= 1, "no live figure on the pages");

  await browser.close();
  server.s.close();
  console.log(`site-test: ${pages.length} pages, ${links} links into the site, ${images} pictures, ` +
              `${runs} commands run in the page`);
  console.log(`site-test: ${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}

main().catch((e) => { console.log("site-test: " + (e && e.stack || e)); process.exit(1); });
