// The seeded generator of the randomised tests (JS random calls, browser soak): mulberry32, the
// one the lesson variants use (www/js/lessons/variants.js). Not a test file itself.
export { mulberry32 as prng } from '../../www/js/lessons/variants.js';
