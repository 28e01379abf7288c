// Runs the Khronos glTF validator on each file named on the command line; prints one JSON line
// per file ({file, errors, warnings, messages: the first errors and warnings}) and exits 1 when
// any file has an error.
'use strict';
const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

async function validate(file) {
    const folder = path.dirname(file);
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        externalResourceFunction: (uri) =>
            Promise.resolve(new Uint8Array(fs.readFileSync(path.join(folder, decodeURIComponent(uri))))),
    });
    const issues = report.issues;
    // Errors (severity 0) and warnings (1), for the reader of a failed test.
    const errors = issues.messages.filter((message) => message.severity <= 1);
    console.log(JSON.stringify({
        file,
        errors: issues.numErrors,
        warnings: issues.numWarnings,
        messages: errors.slice(0, 5).map((message) => message.code + ' ' + message.message),
    }));
    return issues.numErrors;
}

(async () => {
    let errors = 0;
    for (const file of process.argv.slice(2)) errors += await validate(file);
    process.exitCode = errors > 0 ? 1 : 0;
})().catch((error) => {
    console.error(error.message);
    process.exitCode = 2;
});
