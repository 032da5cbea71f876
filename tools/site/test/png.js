// png.js: what the book's tests compare (site_test.js, wasm_test.js).
"use strict";
const zlib = require("zlib");

// The PNG filters undone (raw: the inflated rows, each after its filter byte;
// w x h pixels of 3 bytes): the pixels. Plain JavaScript, so that
// site_test.js can hand it to the page too.
function unfilter(raw, w, h) {
  const stride = w * 3, px = new Uint8Array(stride * h);
  for (let y = 0; y < h; y++) {
    const f = raw[y * (stride + 1)], o = y * (stride + 1) + 1;
    for (let x = 0; x < stride; x++) {
      const a = x >= 3 ? px[y * stride + x - 3] : 0, b = y ? px[(y - 1) * stride + x] : 0;
      const c = x >= 3 && y ? px[(y - 1) * stride + x - 3] : 0;
      let p = 0;
      if (f === 1) p = a; else if (f === 2) p = b; else if (f === 3) p = (a + b) >> 1;
      else if (f === 4) {
        const q = a + b - c, pa = Math.abs(q - a), pb = Math.abs(q - b), pc = Math.abs(q - c);
        p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      px[y * stride + x] = (raw[o + x] + p) & 255;
    }
  }
  return px;
}

// A PNG's size and RGB pixels (8-bit RGB, no interlace: what the lessons write).
function pngPixels(buf) {
  let i = 8, w = 0, h = 0;
  const idat = [];
  while (i < buf.length) {
    const n = buf.readUInt32BE(i), type = buf.toString("latin1", i + 4, i + 8);
    if (type === "IHDR") { w = buf.readUInt32BE(i + 8); h = buf.readUInt32BE(i + 12); }
    if (type === "IDAT") idat.push(buf.subarray(i + 8, i + 8 + n));
    i += 12 + n;
  }
  return {w, h, px: Buffer.from(unfilter(zlib.inflateSync(Buffer.concat(idat)), w, h))};
}

function sameFile(name, a, b) {
  if (name.endsWith(".png")) {
    const pa = pngPixels(Buffer.from(a)), pb = pngPixels(Buffer.from(b));
    return pa.w === pb.w && pa.h === pb.h && Buffer.compare(pa.px, pb.px) === 0;
  }
  return Buffer.compare(Buffer.from(a), Buffer.from(b)) === 0;
}

// A command the browser build cannot run as the native one does: lesson 10
// on more than one thread, or with x86 SIMD. It must be refused there.
function notInTheBrowser(args) {
  return /(^|\s)--threads\s+([2-9]|\d\d)|(^|\s)--simd\s+(sse2|avx2)/.test(args.join(" "));
}

module.exports = {unfilter, pngPixels, sameFile, notInTheBrowser};
