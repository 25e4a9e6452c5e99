// Parses a TAP file with the third-party tap-parser in strict mode; prints the parse errors and
// exits 1 when there are any, else prints the parsed summary as JSON and exits 0.
// Usage: node validate_tap.js FILE   (NODE_PATH: the build tree's node-tools/node_modules)
'use strict';
const fs = require('fs');
const { Parser } = require('tap-parser');

const errors = [];
const points = [];
function watch(parser, depth) {
    parser.on('parseError', (e) => errors.push(`depth ${depth}: ${e.message}: ${JSON.stringify(e.line || '')}`));
    parser.on('assert', (a) => points.push({ depth, ok: a.ok, id: a.id, name: a.name,
                                             skip: a.skip, todo: a.todo, diag: a.diag || null }));
    parser.on('child', (child) => watch(child, depth + 1));
}
const parser = new Parser({ strict: true });
watch(parser, 0);
parser.on('complete', (results) => {
    for (const failure of results.failures || []) {
        if (failure.tapError) {
            errors.push(`${failure.tapError}: ${JSON.stringify(failure.data || '')}`);
        }
    }
    if (errors.length > 0) {
        console.error(errors.join('\n'));
        process.exit(1);
    }
    console.log(JSON.stringify({ ok: results.ok, count: results.count, pass: results.pass,
                                 fail: results.fail, skip: results.skip, bailout: results.bailout,
                                 plan: results.plan, points }));
});
parser.end(fs.readFileSync(process.argv[2]));
