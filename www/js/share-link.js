// The share link's payload (the part after `#s=`): the playground's state as UTF-8 JSON in
// base64url, and back, with the checks that name what is wrong with a link. The playground
// writes and reads it (editor/session.js, editor/share-dialog.js) and the <screw-bender>
// element's `share` option reads it (element/source.js), so it imports nothing of either.

/** Format version written in saves and share links. */
export const SESSION_VERSION = 1;

/**
 * Longest share-link payload accepted, in base64url characters: 2 000 000, just under
 * Chromium's 2 MiB URL limit (a session with the largest autosaved mesh, 1 MiB, fits). Longer
 * payloads are refused before anything is decoded.
 */
export const MAX_SHARE_CHARS = 2_000_000;

/** Bytes → base64url text (no padding): the alphabet a URL fragment carries unescaped. */
export function bytesToBase64url(bytes) {
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/** Base64url text → bytes; the caller has checked the alphabet and the length. */
export function base64urlToBytes(text) {
  const bin = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  return Uint8Array.from(bin, (c) => c.charCodeAt(0));
}

/** UTF-8 JSON → base64url, and back. */
export function encodeHash(obj) {
  return bytesToBase64url(new TextEncoder().encode(JSON.stringify(obj)));
}

/**
 * Decodes a share-link payload into a session object. Throws an Error saying what is wrong
 * (empty, too long, not base64url, not UTF-8, not JSON, not a session of this version); the
 * session itself is validated by applySession (below).
 */
export function decodeHash(text) {
  if (typeof text !== 'string' || text.length === 0) throw new Error('the link holds no session');
  if (text.length > MAX_SHARE_CHARS) {
    throw new Error(`the link's session is ${text.length} characters long; the limit is ${MAX_SHARE_CHARS}`);
  }
  if (!/^[A-Za-z0-9_-]+$/.test(text) || text.length % 4 === 1) {
    throw new Error('the link is malformed (its session is not base64url text; was it cut off?)');
  }
  const bytes = base64urlToBytes(text);
  let json;
  try {
    json = new TextDecoder('utf-8', { fatal: true }).decode(bytes);
  } catch {
    throw new Error('the link is malformed (its session is not UTF-8 text)');
  }
  let obj;
  try {
    obj = JSON.parse(json);
  } catch (e) {
    throw new Error(`the link is malformed (its session is not JSON: ${e.message})`);
  }
  if (!obj || typeof obj !== 'object' || Array.isArray(obj) || !obj.document) {
    throw new Error('the link holds no session object');
  }
  if (obj.version !== SESSION_VERSION) {
    throw new Error(`the link's session has version ${JSON.stringify(obj.version)}; this page reads version ${SESSION_VERSION}`);
  }
  return obj;
}
