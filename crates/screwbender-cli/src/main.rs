//! `screwbender`: the command-line interface to the ScrewBender motion core.
//!
//! Reads a JSON motion document from FILE or standard input (`-`), writes JSON to standard
//! output. Exit status 0 on success, 2 with a one-line message on standard error for bad usage
//! or bad input.

mod args;
mod compare;
mod export;
mod failure;
mod import;
mod input;
mod output;

use std::io::{self, Write};
use std::process::ExitCode;

use screwbender::{
    presets, Motion, MotionDocument, Polyscrew, Pose, Screw, ScrewBender, ScrewKind,
};
use serde_json::{json, Value};

use args::{number, ArgReader, SubdivisionArgs};
use failure::Failure;
use input::read_document;
use output::Output;

const HELP: &str = "\
screwbender — smooth rigid motions by screw subdivision (Powell & Rossignac)

USAGE:
  screwbender subdivide [OPTIONS] [FILE]         refined motion document on stdout
  screwbender eval --u U [--u U ...] [OPTIONS] [FILE]
                                                 poses of the motion at coarse parameters U
  screwbender screw --t T [--t T ...] [FILE]     screw(p0, T, p1) for a document of two poses
  screwbender preset [ID]                        list presets, or print preset ID as a document
  screwbender compare [--methods a,b,c] [--json] [--open] [FILE]
                                                 metrics of the comparison methods on the poses
                                                 (polyscrew bspline fourpoint jarek slerp
                                                 decoupled kks rb cc0 cc1; default: all that apply)
  screwbender rational [--continuity c0|c1] [--end 18|19] [--triangles [--closing-time T]] [FILE]
                                                 the Chaudhry–Cameron motion's rational Bézier
                                                 control points (JSON), from the poses or from a
                                                 raw triangle sequence (lines t,a,x,y: 10 numbers)
  screwbender export --format glb|gltf|csv [EXPORT OPTIONS] [FILE] -o OUT
                                                 the motion as a glTF 2.0 asset (OUT.glb, or
                                                 OUT.gltf + OUT.bin) or CSV samples (stdout
                                                 without -o)
  screwbender import FILE.glb|.gltf|.csv|.json [--node NAME | --nodes A,B,...] [-o OUT]
                                                 control poses as a motion document
  screwbender help | --help | --version

OPTIONS (subdivide, eval):
  --scheme bspline|fourpoint|jarek   subdivision scheme (default: fourpoint)
  --s S                              use the J_s family with parameter S instead of --scheme
                                     (S=0 4-point, S=0.5 Jarek, S=1 B-spline; direct rules only)
  --rules direct|split-then-tweak    rule set: revised paper's direct rules (default) or the
                                     first version's split-then-tweak rules (also: split)
  --levels N                         subdivision steps (default 5; eval: 0 = plain polyscrew)
  --open                             treat the poses as an open sequence (overrides 'closed')

EXPORT OPTIONS (also --scheme, --s, --rules, --levels, --open as above):
  --tolerance T      adaptive keyframes: linear interpolation stays within T of the motion
                     (default 1e-4 scene units); the keyframe count adapts per screw span
  --fps F            fixed-rate keyframes instead (F per second)
  --times T0,T1,...  time of each control pose (a cycle also gives the time pose 0 returns);
                     default: the document's own times, else 1 s per control span
  --velocities V0,V1,...
                     rate of the motion parameter at each control pose (poses per second,
                     >= 0), '-' for a free key (e.g. -,0.5,-); default: the document's own
  --radius R         the tolerance holds at object points up to R from its origin (default:
                     the preset's mesh, else the placeholder box)
  --point x,y,z      csv: trajectory t,u,x,y,z of this body point (default: poses
                     t,u,x,y,z,qw,qx,qy,qz)
  --control-nodes    glb/gltf: also one empty node per control pose
  --verbose, -v      one summary line (sample count) on standard error
  -o, --output OUT   where to write (see above)
The glTF asset animates the object (the preset's shape, else a box; pip_morph5 morphs
between its shapes by morph targets) and an empty node 'control poses' whose keyframes are
the control poses; 'import' reads that node back.

IMPORT OPTIONS:
  --node NAME        the animated node whose keyframes are the poses (default: 'control poses'
                     if present, else the first animated node)
  --nodes A,B,...    the static transforms of these nodes instead
  --open             an open sequence (default: a cycle when the last pose repeats the first)
  -o, --output OUT   write the document to OUT instead of standard output
  --verbose, -v      the pose count kept on standard error
  --reduce every:K   keep every K-th pose (for dense keyframes, e.g. a sampled CSV)
  --reduce fit:TOL[:RADIUS]
                     keep the fewest poses whose polyscrew stays within TOL of the given poses
                     (at points up to RADIUS from the origin; default 0: the origin)
CSV input: x,y,z,qw,qx,qy,qz per line; optional header (any column order), '#' comments.

FILE is a JSON motion document (default: standard input, also '-'):
  {\"closed\": true, \"poses\": [{\"origin\": [x,y,z], \"rotation\": [w,x,y,z]}, ...]}
a pose may give \"basis\": [I, J, K] (column vectors) instead of \"rotation\"; optional
\"times\": [T0, ...] and \"velocities\": [V0 or null, ...] as --times / --velocities.
Quaternions are [w, x, y, z], scalar first; angles in radians; frames right-handed.

EXAMPLE:
  screwbender preset l_cycle_rotated | screwbender subdivide --scheme jarek --levels 3
";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        // A reader that stops early (`screwbender preset x | head`) is not an error.
        Ok(out) => out.write_stdout(),
        Err(Failure(msg)) => {
            eprintln!("screwbender: {msg}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> Result<Output, Failure> {
    let Some((command, rest)) = args.split_first() else {
        return Err(Failure(
            "no command given (try 'screwbender --help')".into(),
        ));
    };
    match command.as_str() {
        "help" | "--help" | "-h" => Ok(Output::text(HELP.to_string())),
        "--version" | "-V" => Ok(Output::text(format!(
            "screwbender {}\n",
            env!("CARGO_PKG_VERSION")
        ))),
        "subdivide" => subdivide(rest),
        "eval" => eval(rest),
        "screw" => screw_command(rest).map(Output::text),
        "preset" => preset(rest).map(Output::text),
        "compare" => compare_command(rest).map(Output::text),
        "rational" => compare::rational(rest).map(Output::text),
        "export" => export::export(rest),
        "import" => import::import(rest),
        other => Err(Failure(format!(
            "unknown command '{other}' (expected subdivide, eval, screw, preset, compare, rational, export, import; try --help)"
        ))),
    }
}

/// Parsed options shared by the commands.
#[derive(Default)]
struct Options {
    sub: SubdivisionArgs,
    us: Vec<f64>,
    ts: Vec<f64>,
    methods: Vec<String>,
    json: bool,
    file: Option<String>,
}

/// Which options a command accepts.
#[derive(Default)]
struct Accepts {
    subdivision: bool,
    u: bool,
    t: bool,
    compare: bool,
}

fn parse_options(args: &[String], accepts: Accepts) -> Result<Options, Failure> {
    let mut o = Options::default();
    let mut r = ArgReader::new(args);
    while let Some(arg) = r.next_arg() {
        if accepts.subdivision && o.sub.take(arg, &mut r)? {
            continue;
        }
        match arg {
            "--u" if accepts.u => o.us.push(number(arg, &r.value(arg)?)?),
            "--t" if accepts.t => o.ts.push(number(arg, &r.value(arg)?)?),
            "--methods" if accepts.compare => o.methods.push(r.value(arg)?),
            "--json" if accepts.compare => o.json = true,
            "--open" if accepts.compare => o.sub.open = true,
            other => r.positional(other)?,
        }
    }
    // Validate the subdivision options now, so a conflict is reported before reading input.
    o.sub.subdivision(0)?;
    o.file = r.file;
    Ok(o)
}

fn subdivide(args: &[String]) -> Result<Output, Failure> {
    let o = parse_options(
        args,
        Accepts {
            subdivision: true,
            u: false,
            t: false,
            compare: false,
        },
    )?;
    let doc = read_document(o.file.as_deref())?;
    let closed = doc.closed && !o.sub.open;
    let sub = o.sub.subdivision(5)?;
    compare::warn_subdivision(&sub, &doc.poses, closed);
    // The refined poses alone (no span screws: nothing here evaluates the motion between
    // them), checked and named as `ScrewBender::new` checks them.
    let control = Polyscrew::new(doc.poses, closed)?;
    let mut out = MotionDocument::new(sub.apply(control.poses(), closed)?, closed);
    out.name = doc.name;
    Ok(Output::writer(move |w| out.write_json(w)))
}

fn pose_json(p: &Pose) -> Value {
    json!({"origin": p.origin.to_array(), "rotation": p.rotation_wxyz()})
}

fn eval(args: &[String]) -> Result<Output, Failure> {
    let o = parse_options(
        args,
        Accepts {
            subdivision: true,
            u: true,
            t: false,
            compare: false,
        },
    )?;
    if o.us.is_empty() {
        return Err(Failure("eval needs at least one --u U".into()));
    }
    let doc = read_document(o.file.as_deref())?;
    let closed = doc.closed && !o.sub.open;
    let sub = o.sub.subdivision(5)?;
    compare::warn_subdivision(&sub, &doc.poses, closed);
    let motion: Box<dyn Motion> = if sub.levels == 0 {
        Box::new(Polyscrew::new(doc.poses, closed)?)
    } else {
        Box::new(ScrewBender::new(doc.poses, closed, sub)?)
    };
    let header = [("motion", json!(motion.name())), ("closed", json!(closed))];
    // Each pose is evaluated as its line is written.
    Ok(Output::writer(move |w| {
        let poses = o.us.iter().map(|&u| {
            let mut v = pose_json(&motion.pose_at(u));
            v["u"] = json!(u);
            v
        });
        write_pose_lines(w, &header, poses)
    }))
}

fn screw_command(args: &[String]) -> Result<String, Failure> {
    let o = parse_options(
        args,
        Accepts {
            subdivision: false,
            u: false,
            t: true,
            compare: false,
        },
    )?;
    if o.ts.is_empty() {
        return Err(Failure("screw needs at least one --t T".into()));
    }
    let doc = read_document(o.file.as_deref())?;
    if doc.poses.len() != 2 {
        return Err(Failure(format!(
            "poses: screw needs exactly 2 poses, {} given",
            doc.poses.len()
        )));
    }
    let s = Screw::between(&doc.poses[0], &doc.poses[1]);
    let params = match s.parameters() {
        ScrewKind::Identity => json!({"kind": "identity"}),
        ScrewKind::Translation {
            direction,
            distance,
        } => json!({"kind": "translation", "axis": direction.to_array(), "angle": 0.0,
                    "slide": distance}),
        ScrewKind::General(p) => json!({"kind": "screw", "axis": p.axis.to_array(),
            "angle": p.angle, "slide": p.slide, "pitch": p.pitch,
            "point": p.point.to_array(), "foot": p.foot.to_array()}),
    };
    let poses = o.ts.iter().map(|&t| {
        let mut v = pose_json(&s.at(t));
        v["t"] = json!(t);
        v
    });
    let mut out = Vec::new();
    write_pose_lines(&mut out, &[("screw", params)], poses).expect("writing to memory cannot fail");
    Ok(String::from_utf8(out).expect("JSON is UTF-8"))
}

fn compare_command(args: &[String]) -> Result<String, Failure> {
    let o = parse_options(
        args,
        Accepts {
            compare: true,
            ..Accepts::default()
        },
    )?;
    let doc = read_document(o.file.as_deref())?;
    let closed = doc.closed && !o.sub.open;
    Ok(compare::compare(&doc.poses, closed, &o.methods, o.json)?)
}

fn preset(args: &[String]) -> Result<String, Failure> {
    match args {
        [] => {
            let mut s = String::new();
            for sc in presets::all() {
                s += &format!("{:<18} {:<4} {}\n", sc.id, sc.label, sc.description);
            }
            Ok(s)
        }
        [id] => {
            let sc = presets::preset(id).ok_or_else(|| {
                Failure(format!(
                    "unknown preset '{id}' (run 'screwbender preset' for the list)"
                ))
            })?;
            let mut doc = MotionDocument::new(sc.poses, sc.closed);
            doc.name = Some(sc.id.to_string());
            Ok(doc.to_json())
        }
        _ => Err(Failure("preset takes at most one ID".into())),
    }
}

/// Writes a JSON object with the given header fields (in order) and a `poses` array, one pose
/// per line — the same layout as a motion document, so outputs diff and grep well.
fn write_pose_lines(
    w: &mut dyn Write,
    header: &[(&str, Value)],
    poses: impl ExactSizeIterator<Item = Value>,
) -> io::Result<()> {
    w.write_all(b"{\n")?;
    for (key, value) in header {
        writeln!(w, "  {}: {},", json!(key), value)?;
    }
    w.write_all(b"  \"poses\": [\n")?;
    let n = poses.len();
    for (i, p) in poses.enumerate() {
        writeln!(w, "    {p}{}", if i + 1 < n { "," } else { "" })?;
    }
    w.write_all(b"  ]\n}\n")
}
