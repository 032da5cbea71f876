// wasm_test.js: the lessons' browser build (make wasm) against the native
// build, under node (make site-test runs it). For each lesson's default run,
// and each command of a lesson that the pages show (a line of a sh or
// console block that runs build/bin/NN with no shell around it), both
// builds run in a directory of their own that holds the same files (the
// pages' examples, and out/ as make run leaves it, made here), and must agree: the same
// status, the same text printed, the same files written, byte for byte
// (pictures too: the browser build deflates with pako, which gives zlib's
// bytes). A command the browser build cannot run as
// the native one does (lesson 10 on more than one thread, or with x86 SIMD)
// must be refused there in one line with status 2, and is listed.
//
//   node tools/site/test/wasm_test.js BIN_DIR WASM_BIN_DIR WORK_DIR
"use strict";
const fs = require("fs");
const path = require("path");
const {spawnSync} = require("child_process");
const {runLesson, filesUnder, loadLesson} = require("../wasm/run.js");
const {notInTheBrowser} = require("./not_in_the_browser.js");

const [bin, wasmBin, work] = process.argv.slice(2).map((p) => path.resolve(p));
process.setMaxListeners(0); // each instance of a lesson under node listens to the process
let passed = 0, failed = 0;
function check(ok, what) {
  if (ok) passed++;
  else { failed++; console.log("FAIL: " + what); }
}

// The pages' commands of lesson programs: [lesson, args].
function pageCommands() {
  const out = [];
  for (const page of fs.readdirSync("docs").filter((f) => /^\d\d_.*\.md$/.test(f)).sort()) {
    let lang = null;
    // A line ending in \ goes on on the next one.
    const text = fs.readFileSync(path.join("docs", page), "utf8").replace(/\s*\\\n\s*/g, " ");
    for (const line of text.split("\n")) {
      const fence = line.match(/^```(\w*)/);
      if (fence) { lang = lang === null ? fence[1] : null; continue; }
      if (lang !== "sh" && lang !== "console") continue;
      let cmd = lang === "console" ? (line.startsWith("$ ") ? line.slice(2) : null) : line;
      if (!cmd) continue;
      cmd = cmd.replace(/\s+#.*$/, "").trim();
      const m = cmd.match(/^build\/bin\/(\d\d_\w+)((?:\s+[^\s|&;<>()$`\\'"*?]+)*)$/);
      if (m) out.push({where: page, lesson: m[1], args: m[2].trim() ? m[2].trim().split(/\s+/) : []});
    }
  }
  return out;
}

// The files every run starts from: the pages' examples, and out/ as make run
// leaves it (each lesson's default run, natively, in a directory of its own).
const lessons = fs.readdirSync(wasmBin).filter((f) => /^\d\d_\w+$/.test(f)).sort();
const staging = path.join(work, "make-run");
fs.rmSync(staging, {recursive: true, force: true});
fs.mkdirSync(staging, {recursive: true});
for (const l of lessons) spawnSync(path.join(bin, l), [], {cwd: staging});
const base = filesUnder("docs/examples", "docs/examples/").concat(filesUnder(path.join(staging, "out"), "out/"));
let runs = 0;
function freshDir() {
  const d = path.join(work, String(runs++));
  fs.rmSync(d, {recursive: true, force: true});
  for (const [rel, bytes] of base) {
    fs.mkdirSync(path.dirname(path.join(d, rel)), {recursive: true});
    fs.writeFileSync(path.join(d, rel), bytes);
  }
  return d;
}

async function compare(lesson, args, where) {
  const label = `${where}: ${lesson} ${args.join(" ")}`.trim();
  const dir = freshDir();
  // Lesson 10 natively as the browser runs it: one thread, plain C blocks.
  const as = lesson === "10_fast_raster" ? ["--threads", "1", "--simd", "none"] : [];
  const native = spawnSync(path.join(bin, lesson), [...args, ...as], {cwd: dir, encoding: "utf8"});
  const nativeFiles = new Map(filesUnder(dir));
  const {factory, wasm} = loadLesson(wasmBin, lesson);
  const r = await runLesson(factory, wasm, args, base);
  const browserOnly = notInTheBrowser(args);
  if (browserOnly) {
    check(r.status === 2 && r.printed.split("\n").filter(Boolean).length === 1,
          `${label}: the browser build should refuse it in one line, status 2 (got ${r.status}: ${r.printed})`);
    console.log(`  not in the browser: ${label}: ${r.printed.trim()}`);
    return;
  }
  check(r.status === native.status, `${label}: status ${r.status} in the browser, ${native.status} native`);
  check(r.stdout === native.stdout, `${label}: prints\n${r.stdout}native:\n${native.stdout}`);
  check(r.stderr === native.stderr, `${label}: says\n${r.stderr}native:\n${native.stderr}`);
  // Every file after the run: what it started with, and what it wrote over it.
  const wasmFiles = new Map(base.concat(r.written));
  check([...wasmFiles.keys()].sort().join() === [...nativeFiles.keys()].sort().join(),
        `${label}: after the run the browser build has ${[...wasmFiles.keys()]}, the native one ${[...nativeFiles.keys()]}`);
  for (const [name, bytes] of nativeFiles)
    if (wasmFiles.has(name)) check(Buffer.compare(Buffer.from(bytes), Buffer.from(wasmFiles.get(name))) === 0, `${label}: ${name} differs`);
}

(async () => {
  check(lessons.length === 10, `${lessons.length} lessons in ${wasmBin}, not 10`);
  for (const l of lessons) await compare(l, [], "default run");
  const cmds = pageCommands();
  for (const c of cmds) await compare(c.lesson, c.args, c.where);
  console.log(`wasm-test: ${lessons.length} default runs and ${cmds.length} page commands, native against the browser build`);
  console.log(`wasm-test: ${passed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
})().catch((e) => { console.log("wasm-test: " + (e && e.stack || e)); process.exit(1); });
