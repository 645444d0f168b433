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

/** UTF-8 JSON → base64url, and back. */
export function encodeHash(obj) {
  const bytes = new TextEncoder().encode(JSON.stringify(obj));
  let bin = '';
  for (const b of bytes) bin += String.fromCharCode(b);
  return btoa(bin).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
}
export function decodeHash(text) {
  const b64 = text.replace(/-/g, '+').replace(/_/g, '/');
  const bin = atob(b64);
  const bytes = Uint8Array.from(bin, (c) => c.charCodeAt(0));
  return JSON.parse(new TextDecoder().decode(bytes));
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
