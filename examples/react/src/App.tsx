// The example app: one editable figure driven by React state (props in, events out), figures
// added and removed by a list, and a figure made by mount() inside an effect.
import { useEffect, useRef, useState } from 'react';
// Defines <screw-bender> and declares it in React's JSX namespace.
import { mount, type ChangeDetail, type ScrewBenderElement, type TimeDetail } from 'screwbender/react';

const PRESETS = ['l_cycle_rotated', 'circle4'] as const;
const TWO_POSES = {
  closed: false,
  poses: [
    { origin: [0, 0, 0], rotation: [1, 0, 0, 0] },
    { origin: [3, 1, 1], rotation: [0.5, 0.5, 0.5, 0.5] },
  ],
};

/** A figure made by mount() in an effect; its cleanup destroys it. */
function MountedFigure({ levels }: { levels: number }) {
  const host = useRef<HTMLDivElement>(null);
  const handle = useRef<ReturnType<typeof mount> | null>(null);
  useEffect(() => {
    const h = mount(host.current!, { scene: 'circle4', levels, controls: 'none' });
    handle.current = h;
    return () => {
      h.destroy();
      handle.current = null;
    };
    // The figure is made once; later levels go through its options below.
  }, []);
  useEffect(() => {
    if (handle.current) handle.current.options = { levels };
  }, [levels]);
  return <div ref={host} className="mounted" data-testid="mounted">Figure made by mount()</div>;
}

export function App() {
  const fig = useRef<ScrewBenderElement>(null);
  const [preset, setPreset] = useState<(typeof PRESETS)[number]>('l_cycle_rotated');
  const [levels, setLevels] = useState(3);
  const [doc, setDoc] = useState<object | null>(null);
  const [time, setTime] = useState<TimeDetail | null>(null);
  const [timeEvents, setTimeEvents] = useState(0);
  const [selected, setSelected] = useState(-1);
  const [changes, setChanges] = useState(0);
  const [moved, setMoved] = useState<number | null>(null);
  const [playing, setPlaying] = useState(false);
  const [extra, setExtra] = useState<number[]>([]);
  const [showMounted, setShowMounted] = useState(true);

  return (
    <main>
      <h1>screwbender in React 19</h1>
      <div className="controls">
        <label>
          Preset{' '}
          <select data-testid="preset" value={preset} onChange={(e) => { setDoc(null); setPreset(e.target.value as typeof preset); }}>
            {PRESETS.map((p) => <option key={p} value={p}>{p}</option>)}
          </select>
        </label>
        <button type="button" data-testid="levels-down" onClick={() => setLevels((l) => Math.max(0, l - 1))}>levels −</button>
        <output data-testid="levels">{levels}</output>
        <button type="button" data-testid="levels-up" onClick={() => setLevels((l) => Math.min(7, l + 1))}>levels +</button>
        <button type="button" data-testid="document" onClick={() => setDoc(TWO_POSES)}>Two poses (document)</button>
        <button type="button" data-testid="seek" onClick={() => fig.current?.seek(1)}>Seek 1 s</button>
        <button type="button" data-testid="play" onClick={() => (playing ? fig.current?.pause() : fig.current?.play())}>{playing ? 'Pause' : 'Play'}</button>
      </div>
      {/* A document figure and a preset figure are two elements (the key): a figure's source is one or the other. */}
      <screw-bender
        key={doc ? 'document' : 'preset'}
        ref={fig}
        data-testid="figure"
        {...(doc ? { document: doc } : { scene: preset })}
        levels={levels}
        editable
        controls="full"
        ontime={(e) => { setTime(e.detail); setTimeEvents((n) => n + 1); }}
        onselect={(e) => setSelected(e.detail.index)}
        onchange={(e: CustomEvent<ChangeDetail>) => { setChanges((n) => n + 1); setMoved(e.detail.index); }}
        onplay={() => setPlaying(true)}
        onpause={() => setPlaying(false)}
      >
        The figure follows the app's state.
      </screw-bender>
      <dl className="state">
        <dt>time</dt><dd data-testid="time">{time ? time.t.toFixed(2) : '–'}</dd>
        <dt>time events</dt><dd data-testid="time-events">{timeEvents}</dd>
        <dt>selected pose</dt><dd data-testid="selected">{selected}</dd>
        <dt>changes</dt><dd data-testid="changes">{changes}</dd>
        <dt>pose moved</dt><dd data-testid="moved">{moved ?? '–'}</dd>
        <dt>playing</dt><dd data-testid="playing">{String(playing)}</dd>
      </dl>
      <div className="controls">
        <button type="button" data-testid="add" onClick={() => setExtra((x) => [...x, (x.at(-1) ?? 0) + 1])}>Add a figure</button>
        <button type="button" data-testid="remove" onClick={() => setExtra((x) => x.slice(0, -1))}>Remove a figure</button>
        <button type="button" data-testid="toggle-mounted" onClick={() => setShowMounted((s) => !s)}>Toggle the mount() figure</button>
      </div>
      <div className="row" data-testid="extra">
        {extra.map((k) => <screw-bender key={k} scene={PRESETS[k % 2]} controls="none" strobe={8}>Figure {k}</screw-bender>)}
      </div>
      {showMounted && <MountedFigure levels={levels} />}
    </main>
  );
}
