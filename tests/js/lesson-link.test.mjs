// The lesson link (www/js/lessons/link.js) and the lesson drafts (www/js/lessons/drafts.js),
// without a browser: a lesson goes into a link and comes back the same, a cut or altered link
// and an oversized one are refused with words, a lesson past the length limit gets the
// message; drafts are listed newest first, deleted and restored with their date, and a broken
// entry is skipped.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { describe, it } from 'node:test';
import { fileURLToPath } from 'node:url';
import { deflateSync } from 'fflate';
import { lessonFromLink, lessonLink, linkPayload, MAX_LINK_CHARS } from '../../www/js/lessons/link.js';
import { deleteDraft, listDrafts, readDraft, restoreDraft, saveDraft, LESSON_DRAFT_PREFIX, MAX_LESSON_DRAFTS } from '../../www/js/lessons/drafts.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const PAGE = 'https://example.org/screwbender/index.html';

describe('lesson link', () => {
  const text = fs.readFileSync(path.join(ROOT, 'www/lessons/01-screw.json'), 'utf8');

  it('carries a lesson file and gives it back byte for byte, shorter than the file', () => {
    const { url, error } = lessonLink(text, PAGE);
    assert.equal(error, null);
    assert.ok(url.startsWith(`${PAGE}#lesson=`));
    assert.match(url.slice(PAGE.length), /^#lesson=[A-Za-z0-9_-]+$/);
    assert.ok(url.length < text.length, `${url.length} characters for a ${text.length}-byte file`);
    assert.equal(lessonFromLink(url), text);
    assert.equal(lessonFromLink(url.slice(url.indexOf('#'))), text);
    assert.equal(linkPayload('#s=abc'), null);
  });

  it('refuses a lesson whose link would pass the limit, with the length and what to do', () => {
    let seed = 3;
    const noise = Array.from({ length: 12000 }, () => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return 'abcdefghijklmnopqrstuvwxyz0123456789'[seed % 36];
    }).join('');
    const big = JSON.stringify({ id: 'big', title: 'Big', steps: [{ title: 'a', text: noise }] });
    const { url, error } = lessonLink(big, PAGE);
    assert.ok(url === null, 'no link is made');
    const n = Number(error.match(/would be (\d+) characters/)[1]);
    assert.ok(n > MAX_LINK_CHARS);
    assert.match(error, /Save the \.json file/);
  });

  it('names what is wrong with a broken link', () => {
    const { url } = lessonLink('{"id":"x"}', PAGE);
    assert.throws(() => lessonFromLink(PAGE), /no #lesson= part/);
    assert.throws(() => lessonFromLink(`${PAGE}#lesson=ab$cd`), /malformed/);
    assert.throws(() => lessonFromLink(url.slice(0, -3)), /malformed|cut off/);
    assert.throws(() => lessonFromLink(`#lesson=${'A'.repeat(8 * MAX_LINK_CHARS + 4)}`), /at most/);
    // A small payload that unpacks past the largest lesson is refused after unpacking.
    const bomb = Buffer.from(deflateSync(new Uint8Array(600 * 1024).fill(32), { level: 9 })).toString('base64url');
    assert.throws(() => lessonFromLink(`#lesson=${bomb}`), /a lesson may have at most/);
  });
});

describe('lesson drafts', () => {
  const store = new Map();
  globalThis.window = /** @type {any} */ ({
    localStorage: {
      get length() {
        return store.size;
      },
      key: (i) => [...store.keys()][i] ?? null,
      getItem: (k) => store.get(k) ?? null,
      setItem: (k, v) => void store.set(k, String(v)),
      removeItem: (k) => void store.delete(k),
    },
  });

  it('keeps several named, dated drafts, newest first; a deleted one comes back as it was', () => {
    assert.equal(saveDraft({ id: 'a', name: 'First', lesson: { id: 'a', steps: [] }, savedAt: 1000 }), true);
    assert.equal(saveDraft({ id: 'b', name: 'Second', lesson: { id: 'b', steps: [] }, savedAt: 2000 }), true);
    store.set(`${LESSON_DRAFT_PREFIX}broken`, '{not json');
    assert.deepEqual(listDrafts().map((d) => [d.id, d.name, d.savedAt]), [['b', 'Second', 2000], ['a', 'First', 1000]]);
    const gone = deleteDraft('b');
    assert.equal(gone.name, 'Second');
    assert.equal(readDraft('b'), null);
    assert.deepEqual(listDrafts().map((d) => d.id), ['a']);
    restoreDraft(gone);
    assert.deepEqual(readDraft('b'), gone);
    assert.equal(deleteDraft('nope'), null);
  });

  it('past the limit the oldest draft gives way; saving a kept draft again drops none', () => {
    for (let k = 0; k < MAX_LESSON_DRAFTS + 3; k++) saveDraft({ id: `n${k}`, name: `N${k}`, lesson: { steps: [] }, savedAt: 10000 + k });
    const ids = listDrafts().map((d) => d.id);
    assert.equal(ids.length, MAX_LESSON_DRAFTS);
    assert.equal(ids.at(-1), 'n3');
    saveDraft({ id: 'n3', name: 'N3', lesson: { steps: [] }, savedAt: 99999 });
    assert.equal(listDrafts().length, MAX_LESSON_DRAFTS);
    assert.equal(listDrafts()[0].id, 'n3');
  });
});
