// run.js: a lesson of the browser build (make wasm) run under node, as a
// terminal runs the native one; and runLesson, which the book's page worker
// (tools/site/worker.js) uses too.
//
//   node tools/site/wasm/run.js WASM_BIN_DIR DIR LESSON [ARG ...]
//
// The lesson runs in an in-memory file system whose working directory holds
// the tree's example files (docs/examples/, as on the pages) and whatever
// DIR holds; it prints what it prints, and every file it writes there is
// copied back into DIR; run.js exits with the lesson's status.
// runLesson() is what the book's page worker does with the same build.
"use strict";
const node = typeof module !== "undefined" && typeof require === "function";
const fs = node ? require("fs") : null;
const path = node ? require("path") : null;

// Every file under dir, as [relative path, bytes].
function filesUnder(dir, prefix = "") {
  const out = [];
  if (!fs.existsSync(dir)) return out;
  for (const e of fs.readdirSync(dir, {withFileTypes: true})) {
    const rel = prefix + e.name, p = path.join(dir, e.name);
    if (e.isDirectory()) out.push(...filesUnder(p, rel + "/"));
    else if (e.isFile()) out.push([rel, fs.readFileSync(p)]);
  }
  return out;
}

function sameBytes(a, b) {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

// The lesson (factory: the module of build/wasm/bin/NN, wasm: its bytes) on
// args, with the given input files in its working directory /work. Returns
// its status, what it printed (printed: stdout and stderr in the order they
// came; stdout, stderr: each alone) and the files it wrote or changed, as
// [path, bytes].
async function runLesson(factory, wasm, args, inputs) {
  const printed = [], stdout = [], stderr = [];
  let status = null;
  const mod = await factory({
    wasmBinary: wasm, noInitialRun: true,
    print: (s) => { printed.push(s); stdout.push(s); },
    printErr: (s) => { printed.push(s); stderr.push(s); },
    quit: (code) => { if (status === null) status = code; },
  });
  mod._umask(0o022); // emscripten's own leaves the atomic outputs unreadable
  const before = new Map();
  for (const [rel, bytes] of inputs) {
    const full = "/work/" + rel;
    let d = "";
    for (const part of full.split("/").slice(0, -1).filter(Boolean)) {
      d += "/" + part;
      try { mod.FS.mkdir(d); } catch (e) { /* there already */ }
    }
    mod.FS.writeFile(full, bytes);
    before.set(rel, bytes);
  }
  try { mod.FS.mkdir("/work"); } catch (e) { /* there already */ }
  mod.FS.chdir("/work");
  try {
    const r = mod.callMain(args);
    if (status === null) status = r;
  } catch (e) {
    if (status === null) status = e && typeof e.status === "number" ? e.status : 134;
  }
  const written = [];
  (function walk(dir, rel) {
    for (const name of mod.FS.readdir(dir)) {
      if (name === "." || name === "..") continue;
      const full = dir + "/" + name, r = rel + name, st = mod.FS.stat(full);
      if (mod.FS.isDir(st.mode)) walk(full, r + "/");
      else {
        const bytes = mod.FS.readFile(full);
        const old = before.get(r);
        if (!old || !sameBytes(old, bytes)) written.push([r, bytes]);
      }
    }
  })("/work", "");
  const text = (lines) => lines.join("\n") + (lines.length ? "\n" : "");
  return {status: status === null ? 0 : status, printed: text(printed), stdout: text(stdout),
          stderr: text(stderr), written};
}

// Under node: the lesson of the browser build in bin (its module factory
// and its wasm bytes), with the deflate its PNGs need (pako, which make wasm
// puts beside the lessons, and the page's worker loads as a script).
function loadLesson(bin, lesson) {
  globalThis.pako = require(path.resolve(bin, "pako_deflate.min.js"));
  return {factory: require(path.resolve(bin, lesson)),
          wasm: fs.readFileSync(path.resolve(bin, lesson + ".wasm"))};
}

if (node) module.exports = {runLesson, filesUnder, loadLesson};
else self.runLesson = runLesson;

if (node && require.main === module) {
  const [bin, dir, lesson, ...args] = process.argv.slice(2);
  const {factory, wasm} = loadLesson(bin, lesson);
  const inputs = filesUnder("docs/examples", "docs/examples/").concat(filesUnder(dir));
  runLesson(factory, wasm, args, inputs).then((r) => {
    process.stdout.write(r.printed);
    for (const [rel, bytes] of r.written) {
      fs.mkdirSync(path.dirname(path.join(dir, rel)), {recursive: true});
      fs.writeFileSync(path.join(dir, rel), bytes);
    }
    process.exit(r.status);
  });
}
