//! `screwbender`: the command-line interface to the ScrewBender motion core.
//!
//! Reads a JSON motion document from FILE or standard input (`-`), writes JSON to standard
//! output. Exit status 0 on success, 2 with a one-line message on standard error for bad usage
//! or bad input.

mod args;
mod cli;
mod compare;
mod export;
mod failure;
mod fit;
mod import;
mod input;
mod output;

use std::ffi::OsString;
use std::io::{self, Write};
use std::process::ExitCode;

use clap_complete::Shell;

use screwbender::{
    presets, Motion, MotionDocument, Polyscrew, Pose, Screw, ScrewBender, ScrewKind,
};
use serde_json::{json, Value};

use cli::{Command, CompareArgs, EvalArgs, Parsed, PresetArgs, ScrewArgs, SubdivideArgs};
use failure::Failure;
use input::read_document;
use output::Output;

fn main() -> ExitCode {
    match run(std::env::args_os().collect()) {
        // A reader that stops early (`screwbender preset x | head`) is not an error.
        Ok(out) => out.write_stdout(),
        Err(Failure(msg)) => {
            eprintln!("screwbender: {msg}");
            ExitCode::from(2)
        }
    }
}

fn run(args: Vec<OsString>) -> Result<Output, Failure> {
    let command = match cli::parse(args)? {
        Parsed::Run(command) => command,
        Parsed::Print(text) => return Ok(Output::text(text)),
    };
    match *command {
        Command::Subdivide(a) => subdivide(a),
        Command::Eval(a) => eval(a),
        Command::Screw(a) => screw_command(a).map(Output::text),
        Command::Preset(a) => preset(a).map(Output::text),
        Command::Compare(a) => compare_command(a).map(Output::text),
        Command::Rational(a) => compare::rational(a).map(Output::text),
        Command::Export(a) => export::export(a),
        Command::Import(a) => import::import(a),
        Command::Fit(a) => fit::fit(a),
        Command::Completions { shell } => Ok(completions(shell)),
        Command::Man { command } => man(command.as_deref()),
    }
}

/// The completion script for `shell`, made whole before it is written (the generator cannot
/// report a write error, so a reader that stops early must not meet it).
fn completions(shell: Shell) -> Output {
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut cli::command(), "screwbender", &mut script);
    Output::writer(move |w| w.write_all(&script))
}

/// The manual page of screwbender, or of one of its commands, in roff.
fn man(command: Option<&str>) -> Result<Output, Failure> {
    let mut cmd = cli::command();
    // Built, a command knows its full name (`screwbender compare`) for its synopsis.
    cmd.build();
    let cmd = match command {
        None => cmd,
        Some(name) => {
            let sub = cmd.find_subcommand(name).cloned().ok_or_else(|| {
                Failure(format!(
                    "man: unknown command '{name}' (try 'screwbender man --help')"
                ))
            })?;
            sub.name(format!("screwbender-{name}"))
                .version(env!("CARGO_PKG_VERSION"))
        }
    };
    let mut page = Vec::new();
    clap_mangen::Man::new(cmd)
        .render(&mut page)
        .map_err(|e| Failure(format!("writing the manual page: {e}")))?;
    Ok(Output::writer(move |w| w.write_all(&page)))
}

fn subdivide(a: SubdivideArgs) -> Result<Output, Failure> {
    // The subdivision options are checked before the input is read.
    let sub = a.sub.subdivision()?;
    let doc = read_document(a.file.as_deref())?;
    let closed = doc.closed && !a.sub.open;
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

fn eval(a: EvalArgs) -> Result<Output, Failure> {
    let sub = a.sub.subdivision()?;
    if a.us.is_empty() {
        return Err(Failure("eval needs at least one --u U".into()));
    }
    let doc = read_document(a.file.as_deref())?;
    let closed = doc.closed && !a.sub.open;
    compare::warn_subdivision(&sub, &doc.poses, closed);
    let motion: Box<dyn Motion> = if sub.levels == 0 {
        Box::new(Polyscrew::new(doc.poses, closed)?)
    } else {
        Box::new(ScrewBender::new(doc.poses, closed, sub)?)
    };
    let header = [("motion", json!(motion.name())), ("closed", json!(closed))];
    // Each pose is evaluated as its line is written.
    Ok(Output::writer(move |w| {
        let poses = a.us.iter().map(|&u| {
            let mut v = pose_json(&motion.pose_at(u));
            v["u"] = json!(u);
            v
        });
        write_pose_lines(w, &header, poses)
    }))
}

fn screw_command(a: ScrewArgs) -> Result<String, Failure> {
    if a.ts.is_empty() {
        return Err(Failure("screw needs at least one --t T".into()));
    }
    let doc = read_document(a.file.as_deref())?;
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
    let poses = a.ts.iter().map(|&t| {
        let mut v = pose_json(&s.at(t));
        v["t"] = json!(t);
        v
    });
    let mut out = Vec::new();
    write_pose_lines(&mut out, &[("screw", params)], poses).expect("writing to memory cannot fail");
    Ok(String::from_utf8(out).expect("JSON is UTF-8"))
}

fn compare_command(a: CompareArgs) -> Result<String, Failure> {
    let doc = read_document(a.file.as_deref())?;
    let closed = doc.closed && !a.open;
    Ok(compare::compare(&doc.poses, closed, &a.methods, a.json)?)
}

fn preset(a: PresetArgs) -> Result<String, Failure> {
    match a.id {
        None => {
            let mut s = String::new();
            for sc in presets::all() {
                let name = presets::display(sc.id).name;
                s += &format!("{:<18} {:<4} {name}: {}\n", sc.id, sc.label, sc.description);
            }
            Ok(s)
        }
        Some(id) => {
            let sc = presets::preset(&id).ok_or_else(|| {
                Failure(format!(
                    "unknown preset '{id}' (run 'screwbender preset' for the list)"
                ))
            })?;
            let mut doc = MotionDocument::new(sc.poses, sc.closed);
            doc.name = Some(sc.id.to_string());
            Ok(doc.to_json())
        }
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
