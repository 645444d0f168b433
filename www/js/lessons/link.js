// The lesson link: a page address that carries a whole lesson file in its fragment
// (`index.html#lesson=<payload>`), so a teacher can hand a lesson to students with no hosting.
// The payload is the lesson's JSON, deflated (the vendored fflate, as the SCORM zip uses) and
// written as base64url (the share link's coding, share-link.js). A fragment never reaches
// the server; its length is bounded by what mail, chat and LMS text fields pass on intact, not
// by the browser, so links past MAX_LINK_CHARS are refused with a message that says what to do
// instead.
import { deflateSync, inflateSync, strFromU8, strToU8 } from '../../vendor/fflate.min.mjs';
import { base64urlToBytes, bytesToBase64url } from '../share-link.js';
import { MAX_LESSON_BYTES } from './format.js';

/** The fragment's key: `#lesson=…`. */
export const LINK_KEY = 'lesson';
/**
 * Longest lesson link made, in characters of the whole address: 8000. Browsers take far longer
 * addresses, but mail programs, chats and LMS link fields cut or refuse them well before
 * Chromium's 2 MiB; 8000 is what common servers and link fields pass on.
 */
export const MAX_LINK_CHARS = 8000;

/** Longest payload read from a link (links made here are far shorter; others are refused before unpacking). */
const MAX_PAYLOAD_CHARS = 8 * MAX_LINK_CHARS;

/** The page's address without query or fragment: where a lesson link opens. */
const pageAddress = () => `${location.origin}${location.pathname}`;

/**
 * The lesson link of lesson file `text` (JSON): {url} or, where it is too long, {error} in words
 * for the teacher, with the length and what to do instead.
 */
export function lessonLink(text, page = pageAddress()) {
  const payload = bytesToBase64url(deflateSync(strToU8(text), { level: 9 }));
  const url = `${page}#${LINK_KEY}=${payload}`;
  if (url.length > MAX_LINK_CHARS) {
    return {
      url: null,
      error: `This lesson's link would be ${url.length} characters long; links longer than ${MAX_LINK_CHARS} are cut off by many mail programs, chats and LMS link fields. Save the .json file and hand it out, or use Download for an LMS, instead.`,
    };
  }
  return { url, error: null };
}

/** The payload of a lesson link's fragment (`#lesson=…`), or null when `hash` is no lesson link. */
export function linkPayload(hash) {
  const m = typeof hash === 'string' ? hash.match(new RegExp(`^#?${LINK_KEY}=(.*)$`)) : null;
  return m ? m[1] : null;
}

/**
 * The lesson file's text from a lesson link (a whole address or its fragment). Throws an Error
 * saying what is wrong (no lesson in it, cut off, too large, not a lesson's text).
 */
export function lessonFromLink(link) {
  const hash = link.includes('#') ? link.slice(link.indexOf('#')) : link;
  const payload = linkPayload(hash.trim());
  if (payload === null) throw new Error('the link holds no lesson (it has no #lesson= part)');
  if (!/^[A-Za-z0-9_-]+$/.test(payload) || payload.length % 4 === 1) throw new Error('the lesson link is malformed (was it cut off?)');
  // Bounded before unpacking: deflate expands at most about a thousandfold.
  if (payload.length > MAX_PAYLOAD_CHARS) throw new Error(`the lesson link is ${payload.length} characters long; a lesson link may have at most ${MAX_PAYLOAD_CHARS}`);
  let bytes;
  try {
    bytes = inflateSync(base64urlToBytes(payload));
  } catch {
    throw new Error('the lesson link is malformed (its lesson cannot be unpacked; was it cut off?)');
  }
  if (bytes.length > MAX_LESSON_BYTES) throw new Error(`the lesson in the link is ${bytes.length} bytes; a lesson may have at most ${MAX_LESSON_BYTES}`);
  return strFromU8(bytes);
}
