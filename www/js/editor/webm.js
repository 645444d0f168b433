// A minimal WebM (Matroska) writer for one video track of encoded frames (WebCodecs
// EncodedVideoChunk data): EBML header, Segment { Info (time scale 1 ms, Duration), Tracks (one
// VP8 or VP9 track), Clusters of SimpleBlocks }, a new Cluster at every key frame. Sizes are
// known (the file is written in memory at the end), so players read its duration at once.

/** EBML element ids (Matroska specification). */
const ID = {
  EBML: 0x1a45dfa3, EBMLVersion: 0x4286, EBMLReadVersion: 0x42f7, EBMLMaxIDLength: 0x42f2,
  EBMLMaxSizeLength: 0x42f3, DocType: 0x4282, DocTypeVersion: 0x4287, DocTypeReadVersion: 0x4285,
  Segment: 0x18538067, Info: 0x1549a966, TimecodeScale: 0x2ad7b1, Duration: 0x4489,
  MuxingApp: 0x4d80, WritingApp: 0x5741, Tracks: 0x1654ae6b, TrackEntry: 0xae, TrackNumber: 0xd7,
  TrackUID: 0x73c5, TrackType: 0x83, CodecID: 0x86, Video: 0xe0, PixelWidth: 0xb0,
  PixelHeight: 0xba, Cluster: 0x1f43b675, Timecode: 0xe7, SimpleBlock: 0xa3,
};
/** The WebM codec ids of the WebCodecs codec strings this writer takes. */
const CODEC_IDS = { vp8: 'V_VP8', vp09: 'V_VP9' };

/** The bytes of an element id (its own length marker included). */
function idBytes(id) {
  const out = [];
  for (let v = id; v > 0; v = Math.floor(v / 256)) out.unshift(v & 0xff);
  return out;
}

/** A data size as an EBML variable-length integer (1 to 8 bytes). */
function sizeBytes(n) {
  let len = 1;
  while (len < 8 && n >= 2 ** (7 * len) - 1) len++;
  const out = new Array(len);
  let v = n;
  for (let k = len - 1; k >= 0; k--) {
    out[k] = v % 256;
    v = Math.floor(v / 256);
  }
  out[0] |= 0x80 >> (len - 1);
  return out;
}

/** An element: id, size, then the data (a Uint8Array, or a list of parts to concatenate). */
function el(id, data) {
  const body = data instanceof Uint8Array ? data : concat(data);
  return concat([Uint8Array.from([...idBytes(id), ...sizeBytes(body.length)]), body]);
}

function concat(parts) {
  const out = new Uint8Array(parts.reduce((s, p) => s + p.length, 0));
  let o = 0;
  for (const p of parts) {
    out.set(p, o);
    o += p.length;
  }
  return out;
}

const uint = (id, v) => {
  const b = [];
  for (let x = v; b.length === 0 || x > 0; x = Math.floor(x / 256)) b.unshift(x % 256);
  return el(id, Uint8Array.from(b));
};
const text = (id, s) => el(id, new TextEncoder().encode(s));
const float64 = (id, v) => {
  const b = new Uint8Array(8);
  new DataView(b.buffer).setFloat64(0, v);
  return el(id, b);
};

/**
 * The WebM file of `frames` ({ data: Uint8Array, timestamp: µs, key: bool }, in order, the first
 * a key frame) of a `width` × `height` video in `codec` ('vp8' or a 'vp09…' string) lasting
 * `durationMs`. Throws on an unknown codec or a first frame that is not a key frame.
 */
export function webmFile({ codec, width, height, durationMs, frames }) {
  const codecId = CODEC_IDS[codec.split('.')[0]];
  if (!codecId) throw new Error(`WebM: codec ${codec} is not VP8 or VP9`);
  if (!frames.length || !frames[0].key) throw new Error('WebM: the first frame must be a key frame');
  const header = el(ID.EBML, [
    uint(ID.EBMLVersion, 1), uint(ID.EBMLReadVersion, 1), uint(ID.EBMLMaxIDLength, 4),
    uint(ID.EBMLMaxSizeLength, 8), text(ID.DocType, 'webm'), uint(ID.DocTypeVersion, 2),
    uint(ID.DocTypeReadVersion, 2),
  ]);
  const info = el(ID.Info, [
    uint(ID.TimecodeScale, 1e6), float64(ID.Duration, durationMs),
    text(ID.MuxingApp, 'screwbender'), text(ID.WritingApp, 'screwbender'),
  ]);
  const tracks = el(ID.Tracks, [
    el(ID.TrackEntry, [
      uint(ID.TrackNumber, 1), uint(ID.TrackUID, 1), uint(ID.TrackType, 1), text(ID.CodecID, codecId),
      el(ID.Video, [uint(ID.PixelWidth, width), uint(ID.PixelHeight, height)]),
    ]),
  ]);
  const clusters = [];
  let blocks = [];
  let start = 0;
  const close = () => blocks.length && clusters.push(el(ID.Cluster, [uint(ID.Timecode, start), ...blocks]));
  for (const f of frames) {
    const ms = Math.round(f.timestamp / 1000);
    // A cluster per key frame, and before the block's 16-bit relative time overflows.
    if (f.key || ms - start > 32000) {
      close();
      blocks = [];
      start = ms;
    }
    const rel = ms - start;
    const head = Uint8Array.from([0x81, (rel >> 8) & 0xff, rel & 0xff, f.key ? 0x80 : 0x00]);
    blocks.push(el(ID.SimpleBlock, [head, f.data]));
  }
  close();
  return concat([header, el(ID.Segment, [info, tracks, ...clusters])]);
}
