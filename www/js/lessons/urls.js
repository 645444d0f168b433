// Where lesson files live: the lessons/ folder of the page, and the rule for which URLs a
// `?lesson=` value (or open(name)) may load.

/** The lessons/ folder (lesson files, index.json, README.md). */
export const BASE = new URL('../../lessons/', import.meta.url);

/**
 * The URL of lesson `name` (`?lesson=` value): a bare name means lessons/<name>.json; any other
 * value must resolve to a same-origin file under lessons/. Returns null if it does not.
 */
export function lessonUrl(name) {
  if (typeof name !== 'string' || name === '') return null;
  const file = /^[\w-]+$/.test(name) ? `${name}.json` : name;
  let url;
  try {
    url = new URL(file, /^[\w-]+(\.json)?$/.test(file) ? BASE : location.href);
  } catch {
    return null;
  }
  if (url.origin !== location.origin || !url.pathname.startsWith(BASE.pathname) || !url.pathname.endsWith('.json')) return null;
  return url;
}

/**
 * Resolves a lesson id of lessons/index.json (e.g. `screw`) to its file name there
 * (`01-screw.json`); any other name comes back as it is (a file name, `tour`, a path).
 */
export async function resolveLessonName(name) {
  if (typeof name !== 'string' || !/^[\w-]+$/.test(name)) return name;
  try {
    const r = await fetch(new URL('index.json', BASE), { cache: 'no-store' });
    if (!r.ok) return name;
    const index = await r.json();
    return index.lessons?.find((l) => l.id === name)?.file ?? name;
  } catch {
    return name;
  }
}
