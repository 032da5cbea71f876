// not_in_the_browser.js: what the book's tests (site_test.js, wasm_test.js)
// expect the browser build to refuse.
"use strict";

// A command the browser build cannot run as the native one does: lesson 10
// on more than one thread, or with x86 SIMD. It must be refused there.
function notInTheBrowser(args) {
  return /(^|\s)--threads\s+([2-9]|\d\d)|(^|\s)--simd\s+(sse2|avx2|avx512)/.test(args.join(" "));
}

module.exports = {notInTheBrowser};
