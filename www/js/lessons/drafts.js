// Lesson drafts: the lessons being written in the editor (lessons/editor/), kept in localStorage
// so they survive a reload and are seen by every tab. Several at once, each under its own key
// `screwbender.lessonDraft.<id>` as {id, name, savedAt (ms since 1970), lesson}, so two tabs
// editing two drafts never overwrite each other. A deleted draft is handed back to the caller,
// which keeps it for Undo (restoreDraft). Storage that is broken, full or disabled never throws:
// the functions say so by their result.

/** Prefix of each lesson draft's key. */
export const LESSON_DRAFT_PREFIX = 'screwbender.lessonDraft.';
/** Lesson drafts kept at most: past it the oldest one gives way. */
export const MAX_LESSON_DRAFTS = 30;

/**
 * A lesson draft.
 * @typedef {{id: string, name: string, savedAt: number, lesson: any}} LessonDraft
 */

/** The page's localStorage, or null where the browser gives none. */
function store() {
  try {
    return window.localStorage;
  } catch {
    return null;
  }
}

/** A new draft id. */
export const newDraftId = () => crypto.randomUUID?.() ?? `${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`;

/** The draft under storage key `key`, or null (missing or broken). */
function readKey(s, key) {
  try {
    const d = JSON.parse(s.getItem(key) ?? 'null');
    return d && typeof d === 'object' && typeof d.id === 'string' && d.lesson && typeof d.lesson === 'object'
      ? { id: d.id, name: String(d.name ?? ''), savedAt: Number(d.savedAt) || 0, lesson: d.lesson }
      : null;
  } catch {
    return null;
  }
}

/** Every lesson draft, the newest first. @returns {LessonDraft[]} */
export function listDrafts() {
  const s = store();
  if (!s) return [];
  const out = [];
  try {
    for (let i = 0; i < s.length; i++) {
      const key = s.key(i);
      if (key?.startsWith(LESSON_DRAFT_PREFIX)) {
        const d = readKey(s, key);
        if (d) out.push(d);
      }
    }
  } catch {
    return [];
  }
  return out.sort((a, b) => b.savedAt - a.savedAt);
}

/** Lesson draft `id`, or null. */
export function readDraft(id) {
  const s = store();
  return s ? readKey(s, LESSON_DRAFT_PREFIX + id) : null;
}

/**
 * Keeps `draft` (its savedAt is set to now unless given); past MAX_LESSON_DRAFTS the oldest other
 * draft gives way. Returns true when it was written.
 * @param {{id: string, name: string, lesson: any, savedAt?: number}} draft
 */
export function saveDraft(draft) {
  const s = store();
  if (!s) return false;
  const d = { id: draft.id, name: draft.name, savedAt: draft.savedAt ?? Date.now(), lesson: draft.lesson };
  try {
    // Only a new draft can pass the limit (the editor saves its draft at every change: the
    // others are not read then).
    if (s.getItem(LESSON_DRAFT_PREFIX + d.id) === null) {
      const others = listDrafts().filter((o) => o.id !== d.id);
      for (const o of others.slice(MAX_LESSON_DRAFTS - 1)) s.removeItem(LESSON_DRAFT_PREFIX + o.id);
    }
    s.setItem(LESSON_DRAFT_PREFIX + d.id, JSON.stringify(d));
    return true;
  } catch {
    return false;
  }
}

/** Deletes draft `id`; returns it (for Undo: restoreDraft) or null when there was none. */
export function deleteDraft(id) {
  const s = store();
  const d = readDraft(id);
  if (!s || !d) return null;
  try {
    s.removeItem(LESSON_DRAFT_PREFIX + id);
  } catch {
    return null;
  }
  return d;
}

/** Puts a deleted draft back as it was (its date included). */
export const restoreDraft = (d) => saveDraft(d);

/** Calls `fn()` whenever another tab changes a lesson draft (the storage event). */
export function onDraftsChanged(fn) {
  window.addEventListener('storage', (e) => {
    if (e.key === null || e.key.startsWith(LESSON_DRAFT_PREFIX)) fn();
  });
}
