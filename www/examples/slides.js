// The deck of slides.html: reveal.js (www/vendor/reveal.min.mjs, vendored from npm by
// scripts/serve.d/50-reveal.sh) with its default keys. A figure that has the focus takes the keys
// it uses; every other key, and every key while no figure has the focus, drives the deck.
import Reveal from '../vendor/reveal.min.mjs';

const deck = new Reveal({
  hash: true,
  width: 1000,
  height: 700,
  margin: 0.04,
  transition: 'slide',
  // The print view (?print-pdf) puts one slide on each page.
  pdfMaxPagesPerSlide: 1,
});
deck.initialize();
// For tests and the console.
window.deck = deck;
