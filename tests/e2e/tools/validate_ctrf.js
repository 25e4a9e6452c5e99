// Validates a JSON report against CTRF's published JSON schema (the one the ctrf package ships,
// installed into the build tree) with ajv, formats checked. Prints the errors and exits 1 when
// the report is not valid. Usage: node validate_ctrf.js FILE   (NODE_PATH: node-tools)
'use strict';
const fs = require('fs');
const path = require('path');
const Ajv = require('ajv');
const addFormats = require('ajv-formats');

// The package's entry point sits in dist/, beside the schema it validates with.
const dist = path.dirname(require.resolve('ctrf'));
const schemaFile = fs.readdirSync(dist).filter((name) => /^ctrf-schema-.*\.json$/.test(name))
    .sort().pop();
const schema = JSON.parse(fs.readFileSync(path.join(dist, schemaFile)));
const ajv = new Ajv({ allErrors: true, strict: false });
addFormats(ajv);
const validate = ajv.compile(schema);
const report = JSON.parse(fs.readFileSync(process.argv[2], 'utf8'));
if (!validate(report)) {
    console.error(`${process.argv[2]} is not valid CTRF (${schemaFile}):`);
    console.error(JSON.stringify(validate.errors, null, 2));
    process.exit(1);
}
console.log(`valid CTRF (${schemaFile})`);
