// worker.js: the lessons of the book's pages, run in the browser (site.js
// starts it). A page's Run button sends {id, lesson, args}; the worker loads
// that lesson's browser build (wasm/NN.js and NN.wasm, from make wasm) once,
// runs it with wasm/run.js's runLesson in an in-memory file system holding
// the files of the tree the pages' commands read (inputs.json: the examples
// of docs/examples/, the expected pictures of tests/expected/ the pages
// name) and every file the page's earlier runs wrote (out/...), as a
// terminal in the tree would, and answers
// {id, status, printed, stdout, stderr, written}.
"use strict";
self.importScripts("wasm/run.js", "wasm/pako_deflate.min.js");

const lessons = new Map(); // lesson -> {factory, wasm}
const kept = new Map();    // path -> bytes: what the page's runs wrote
let inputs = null;         // [[path, bytes]]: the tree's files (inputs.json)

async function bytesOf(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`cannot load ${url}: ${r.status}`);
  return new Uint8Array(await r.arrayBuffer());
}

async function load(lesson) {
  if (!lessons.has(lesson)) {
    self.Lesson = undefined;
    self.importScripts(`wasm/${lesson}.js`);
    lessons.set(lesson, {factory: self.Lesson, wasm: await bytesOf(`wasm/${lesson}.wasm`)});
  }
  if (!inputs) {
    const list = await (await fetch("inputs.json")).json();
    inputs = [];
    for (const name of list) inputs.push([name, await bytesOf(name)]);
  }
  return lessons.get(lesson);
}

self.onmessage = async (e) => {
  const {id, lesson, args} = e.data;
  try {
    const {factory, wasm} = await load(lesson);
    const r = await self.runLesson(factory, wasm, args, inputs.concat([...kept]));
    for (const [p, b] of r.written) kept.set(p, b);
    self.postMessage({id, status: r.status, printed: r.printed, stdout: r.stdout,
                      stderr: r.stderr, written: r.written});
  } catch (err) {
    self.postMessage({id, error: String(err && err.message || err)});
  }
};
