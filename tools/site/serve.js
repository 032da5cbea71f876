// serve.js: serves the book's directory over HTTP on 127.0.0.1 (make
// site-serve; site_test.js starts it too). A directory serves its
// index.html; the pages' own files get their types (.c, .h, .diff and .obj
// as text). Only files under the directory are served.
//
//   node tools/site/serve.js [SITE_DIR [PORT]]      (PORT 0: any free port)
"use strict";
const http = require("http");
const fs = require("fs");
const path = require("path");

const TYPES = {
  ".html": "text/html; charset=utf-8", ".css": "text/css; charset=utf-8",
  ".js": "text/javascript; charset=utf-8", ".mjs": "text/javascript; charset=utf-8",
  ".json": "application/json", ".png": "image/png", ".svg": "image/svg+xml",
  ".wasm": "application/wasm", ".pdf": "application/pdf", ".epub": "application/epub+zip",
  ".c": "text/plain; charset=utf-8", ".h": "text/plain; charset=utf-8",
  ".diff": "text/plain; charset=utf-8", ".obj": "text/plain; charset=utf-8",
  ".mtl": "text/plain; charset=utf-8", ".txt": "text/plain; charset=utf-8",
  ".pfm": "application/octet-stream", ".pgm": "image/x-portable-graymap",
};

function serve(dir, port, onReady) {
  const top = path.resolve(dir);
  const server = http.createServer((req, res) => {
    let file;
    try {
      file = path.join(top, decodeURIComponent(new URL(req.url, "http://x").pathname));
    } catch (e) {
      res.writeHead(400).end("bad request\n");
      return;
    }
    if (file !== top && !file.startsWith(top + path.sep)) {
      res.writeHead(403).end("outside the site\n");
      return;
    }
    fs.stat(file, (err, st) => {
      if (!err && st.isDirectory()) file = path.join(file, "index.html");
      fs.readFile(file, (err2, data) => {
        if (err2) {
          res.writeHead(404, {"Content-Type": "text/plain"}).end("not found\n");
          return;
        }
        const type = TYPES[path.extname(file).toLowerCase()] || "application/octet-stream";
        res.writeHead(200, {"Content-Type": type, "Cache-Control": "no-cache"}).end(data);
      });
    });
  });
  server.listen(port, "127.0.0.1", () => onReady(server, server.address().port));
  return server;
}

module.exports = {serve};

if (require.main === module) {
  const dir = process.argv[2] || "build/site";
  const port = Number(process.argv[3] || 8000);
  serve(dir, port, (server, p) => {
    console.log(`site: serving ${dir} on http://127.0.0.1:${p}/ (Ctrl-C stops)`);
  });
}
