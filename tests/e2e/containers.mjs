// Readers of the video containers the playground records (editor/media.js, muxed by
// mediabunny), written here from the formats' specifications rather than taken from the muxer,
// so that a test does not check the muxer with itself: the boxes of an MP4 (ISO BMFF) and the
// elements of a WebM (Matroska EBML), and what the tests ask of them (codec, sample or block
// count, durations and time spans).

/** Frames per second of the videos (editor/media.js FPS). */
export const FPS = 30;

/** The boxes of an ISO BMFF (MP4) byte range: [{type, start, end}] (start: after the header). */
function boxes(bytes, from = 0, to = bytes.length) {
  const out = [];
  let pos = from;
  while (pos + 8 <= to) {
    let size = bytes.readUInt32BE(pos);
    const type = bytes.subarray(pos + 4, pos + 8).toString('latin1');
    let head = 8;
    if (size === 1) {
      size = Number(bytes.readBigUInt64BE(pos + 8));
      head = 16;
    } else if (size === 0) size = to - pos;
    out.push({ type, start: pos + head, end: pos + size });
    pos += size;
  }
  return out;
}

/** The box of `path` (types, e.g. ['moov', 'trak', 'mdia', 'mdhd']), or undefined. */
function box(bytes, path) {
  let range = { start: 0, end: bytes.length };
  for (const type of path) {
    range = boxes(bytes, range.start, range.end).find((b) => b.type === type);
    if (!range) return undefined;
  }
  return range;
}

/**
 * What an MP4 file says: its brand, the sample entry (codec), the track's duration (mdhd,
 * seconds), the number of samples (stsz) and the times of the first and last samples from stts.
 */
export function mp4Info(bytes) {
  const ftyp = box(bytes, ['ftyp']);
  const stbl = ['moov', 'trak', 'mdia', 'minf', 'stbl'];
  const mdhd = box(bytes, ['moov', 'trak', 'mdia', 'mdhd']);
  const v1 = bytes[mdhd.start] === 1;
  const timescale = bytes.readUInt32BE(mdhd.start + (v1 ? 20 : 12));
  const duration = v1 ? Number(bytes.readBigUInt64BE(mdhd.start + 24)) : bytes.readUInt32BE(mdhd.start + 16);
  const stsd = box(bytes, [...stbl, 'stsd']);
  const entry = bytes.subarray(stsd.start + 12, stsd.start + 16).toString('latin1');
  const stsz = box(bytes, [...stbl, 'stsz']);
  const samples = bytes.readUInt32BE(stsz.start + 8);
  const stts = box(bytes, [...stbl, 'stts']);
  let t = 0;
  let counted = 0;
  const runs = bytes.readUInt32BE(stts.start + 4);
  for (let k = 0; k < runs; k++) {
    const n = bytes.readUInt32BE(stts.start + 8 + 8 * k);
    const delta = bytes.readUInt32BE(stts.start + 12 + 8 * k);
    t += n * delta;
    counted += n;
  }
  return {
    brand: bytes.subarray(ftyp.start, ftyp.start + 4).toString('latin1'),
    entry,
    duration: duration / timescale,
    samples,
    sttsSamples: counted,
    sttsSpan: t / timescale,
  };
}

/**
 * What a WebM file says of its time: `duration` (s) from the Duration element of its Info, and
 * `span` (s) from its blocks (the last block's time minus the first's, plus one frame) and their
 * count, and the codec id. Walks the EBML elements, entering Segment, Info, Tracks and Clusters.
 */
export function webmInfo(bytes) {
  const MASTERS = new Set([0x18538067, 0x1549a966, 0x1f43b675, 0x1654ae6b, 0xae, 0xa0]); // Segment, Info, Cluster, Tracks, TrackEntry, BlockGroup
  let pos = 0;
  const vint = (keepMarker) => {
    const first = bytes[pos];
    let len = 1;
    while (len <= 8 && !(first & (0x80 >> (len - 1)))) len++;
    let v = keepMarker ? first : first & (0xff >> len);
    for (let k = 1; k < len; k++) v = v * 256 + bytes[pos + k];
    pos += len;
    return v;
  };
  const uint = (at, n) => {
    let v = 0;
    for (let k = 0; k < n; k++) v = v * 256 + bytes[at + k];
    return v;
  };
  let scale = 1e6; // ns per timecode unit (TimecodeScale's default)
  let duration = NaN;
  let cluster = 0;
  let first = Infinity;
  let last = -Infinity;
  let blocks = 0;
  let codec = '';
  while (pos < bytes.length) {
    const id = vint(true);
    const size = vint(false);
    const start = pos;
    if (MASTERS.has(id)) continue;
    if (id === 0x2ad7b1) scale = uint(start, size);
    else if (id === 0x4489) duration = size === 8 ? bytes.readDoubleBE(start) : bytes.readFloatBE(start);
    else if (id === 0x86) codec = bytes.subarray(start, start + size).toString('latin1');
    else if (id === 0xe7) cluster = uint(start, size);
    else if (id === 0xa3 || id === 0xa1) {
      pos = start;
      vint(false); // track number
      const t = cluster + bytes.readInt16BE(pos);
      first = Math.min(first, t);
      last = Math.max(last, t);
      blocks++;
    }
    pos = start + size;
  }
  return { codec, duration: (duration * scale) / 1e9, span: ((last - first) * scale) / 1e9 + 1 / FPS, blocks };
}
