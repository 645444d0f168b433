// Session state: undo/redo history, autosave to localStorage, share links in the URL hash.

export const STORAGE_KEY = 'screwbender.playground.v1';
/** Session format version written in saves and share links. */
export const SESSION_VERSION = 1;
/** Undo steps kept. */
export const MAX_UNDO = 200;

/** Undo/redo over serialized snapshots (strings). */
export class History {
  constructor() {
    this.undoStack = [];
    this.redoStack = [];
  }
  /** Records `snapshot` (the state *before* an edit). */
  push(snapshot) {
    if (this.undoStack[this.undoStack.length - 1] === snapshot) return;
    this.undoStack.push(snapshot);
    if (this.undoStack.length > MAX_UNDO) this.undoStack.shift();
    this.redoStack.length = 0;
  }
  /** Returns the snapshot to restore, given the current one, or null. */
  undo(current) {
    const s = this.undoStack.pop();
    if (s === undefined) return null;
    this.redoStack.push(current);
    return s;
  }
  redo(current) {
    const s = this.redoStack.pop();
    if (s === undefined) return null;
    this.undoStack.push(current);
    return s;
  }
  get canUndo() {
    return this.undoStack.length > 0;
  }
  get canRedo() {
    return this.redoStack.length > 0;
  }
}

/**
 * Longest share-link payload accepted, in base64url characters: 2 000 000, just under
 * Chromium's 2 MiB URL limit (a session with the largest autosaved mesh, 1 MiB, fits). Longer
 * payloads are refused before anything is decoded.
 */
export const MAX_SHARE_CHARS = 2_000_000;

/** UTF-8 JSON → base64url, and back. */
export function encodeHash(obj) {
  const bytes = new TextEncoder().encode(JSON.stringify(obj));
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}

/**
 * Decodes a share-link payload into a session object. Throws an Error saying what is wrong
 * (empty, too long, not base64url, not UTF-8, not JSON, not a session of this version); the
 * session itself is validated by App.applySession.
 */
export function decodeHash(text) {
  if (typeof text !== 'string' || text.length === 0) throw new Error('the link holds no session');
  if (text.length > MAX_SHARE_CHARS) {
    throw new Error(`the link's session is ${text.length} characters long; the limit is ${MAX_SHARE_CHARS}`);
  }
  if (!/^[A-Za-z0-9_-]+$/.test(text) || text.length % 4 === 1) {
    throw new Error('the link is malformed (its session is not base64url text; was it cut off?)');
  }
  const bin = atob(text.replace(/-/g, '+').replace(/_/g, '/'));
  const bytes = Uint8Array.from(bin, (c) => c.charCodeAt(0));
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

export function loadSaved() {
  try {
    const text = localStorage.getItem(STORAGE_KEY);
    return text ? JSON.parse(text) : null;
  } catch {
    return null;
  }
}

/** Saves; returns an error message when storage is full or unavailable. */
export function save(session) {
  try {
    localStorage.setItem(STORAGE_KEY, JSON.stringify(session));
    return null;
  } catch (e) {
    return `autosave failed: ${e.message}`;
  }
}
