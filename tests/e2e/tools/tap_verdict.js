// The verdict of the reference TAP 14 parser (tap-parser, not strict: as a harness reads a
// program's output) on a TAP file: prints {ok, bailout, count, pass, fail, skip, todo} as JSON.
// Usage: node tap_verdict.js FILE   (NODE_PATH: the build tree's node-tools/node_modules)
'use strict';
const fs = require('fs');
const { Parser } = require('tap-parser');

const parser = new Parser();
parser.on('complete', (results) => {
    console.log(JSON.stringify({ ok: results.ok, bailout: results.bailout, count: results.count,
                                 pass: results.pass, fail: results.fail, skip: results.skip,
                                 todo: results.todo }));
});
parser.end(fs.readFileSync(process.argv[2]));
