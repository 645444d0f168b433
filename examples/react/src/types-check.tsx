// Typed usage of <screw-bender> in React 19's JSX, for `tsc --strict` (not part of the app): what
// must compile, and with @ts-expect-error what the typings must refuse.
import type { CameraChangeDetail, ScrewBenderElement, TimeDetail } from 'screwbender/react';

export function Typed({ onT }: { onT: (d: TimeDetail) => void }) {
  return (
    <>
      <screw-bender
        scene="l_cycle_rotated"
        levels={4}
        strobe="12"
        scheme="fourpoint"
        autoplay
        loop={false}
        controls="full"
        theme="dark"
        camera="iso"
        alt="A rigid motion"
        loading="eager"
        document={{ closed: true, poses: [] }}
        currentTime={1.5}
        playbackRate={-1}
        ontime={(e) => onT(e.detail)}
        onchange={(e) => e.detail.poses.length}
        onselect={(e) => e.detail.index + 1}
        onerror={(e) => e.detail.message.toUpperCase()}
        onplay={(e: Event) => e.type}
        onratechange={(e: Event) => e.type}
        oncamera-change={(e: CustomEvent<CameraChangeDetail>) => e.detail.source === 'user'}
        ref={(el: ScrewBenderElement | null) => el?.seek(0)}
        className="figure"
      >
        caption
      </screw-bender>
      {/* @ts-expect-error: no such control style */}
      <screw-bender controls="maximal" />
      {/* @ts-expect-error: levels is a number */}
      <screw-bender levels={{ n: 4 }} />
      {/* @ts-expect-error: the time event is a CustomEvent of TimeDetail */}
      <screw-bender ontime={(e: CustomEvent<{ other: string }>) => e.detail.other} />
      {/* @ts-expect-error: theme is light or dark */}
      <screw-bender theme="blue" />
    </>
  );
}
