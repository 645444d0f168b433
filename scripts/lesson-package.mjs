#!/usr/bin/env node
// A lesson package for an LMS, from the command line (the page's Lessons menu → "Download for an
// LMS (SCORM)" makes the same zip; both use www/js/lessons/package.js):
//
//   node scripts/lesson-package.mjs --format scorm12|scorm2004 [--mastery 0.8] \
//       [--title TEXT] [--description TEXT] LESSON.json… -o OUT.zip
//
// Several lessons make one course (the package's Lessons menu lists them, in the order given).
// Needs the page built (./scripts/serve.sh): it copies the playground's files from www/ as listed
// in www/pkg-lesson/files.json. Prints the zip's size. docs/teaching/lms.md says how to upload it.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { zipSync } from 'fflate';
import { FILE_LIST, FORMATS, packageZip, planPackage } from '../www/js/lessons/package.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const WWW = path.join(ROOT, 'www');
const USAGE = `usage: node scripts/lesson-package.mjs --format ${Object.keys(FORMATS).join('|')} [--mastery 0.8] [--title TEXT] [--description TEXT] LESSON.json… -o OUT.zip`;

function fail(message) {
  console.error(`lesson-package: ${message}\n${USAGE}`);
  process.exit(2);
}

let args;
try {
  args = parseArgs({
    allowPositionals: true,
    options: {
      format: { type: 'string' },
      mastery: { type: 'string' },
      title: { type: 'string' },
      description: { type: 'string' },
      output: { type: 'string', short: 'o' },
      help: { type: 'boolean', short: 'h' },
    },
  });
} catch (e) {
  fail(e.message);
}
const { values: opt, positionals: lessonFiles } = args;
if (opt.help) {
  console.log(USAGE);
  process.exit(0);
}
if (!opt.format) fail('--format is required');
if (!opt.output) fail('-o OUT.zip is required');
if (!lessonFiles.length) fail('give at least one LESSON.json');

const listFile = path.join(WWW, FILE_LIST);
if (!fs.existsSync(listFile)) fail(`www/${FILE_LIST} is missing: build the page first (./scripts/serve.sh)`);
const list = JSON.parse(fs.readFileSync(listFile, 'utf8'));

let plan;
try {
  const lessons = lessonFiles.map((file) => {
    let text;
    try {
      text = fs.readFileSync(file, 'utf8');
    } catch (e) {
      throw new Error(`${file}: cannot read it (${e.code ?? e.message})`);
    }
    return { file, text };
  });
  plan = planPackage({
    lessons,
    format: opt.format,
    mastery: opt.mastery ?? null,
    title: opt.title,
    description: opt.description,
    list,
    template: fs.readFileSync(path.join(WWW, list.template), 'utf8'),
  });
} catch (e) {
  fail(`${e.message}. Nothing was written.`);
}
const enc = new TextEncoder();
const files = plan.files.map((f) => ({ path: f.path, data: f.text !== undefined ? enc.encode(f.text) : fs.readFileSync(path.join(WWW, f.www)) }));
const zip = packageZip(files, zipSync);
try {
  fs.mkdirSync(path.dirname(path.resolve(opt.output)), { recursive: true });
  fs.writeFileSync(opt.output, zip);
} catch (e) {
  fail(`${opt.output}: cannot write it (${e.code ?? e.message})`);
}
console.log(`${opt.output}: ${FORMATS[opt.format]} package "${plan.title}", ${files.length} files, ${(zip.length / 1e6).toFixed(2)} MB`);
