//! The command line itself: every command, its options and their help (clap's derive API), the
//! overview that `screwbender --help` prints, and turning clap's usage errors into the CLI's
//! one-line `screwbender: …` messages.

use std::ffi::OsString;

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};
use clap_complete::Shell;

use crate::args::{Finite, SubdivisionArgs};
use crate::failure::Failure;

/// The motion document format and the conventions, for every command that reads one.
macro_rules! file_format {
    () => {
        "\
FILE is a JSON motion document (default: standard input, also '-'):
  {\"closed\": true, \"poses\": [{\"origin\": [x,y,z], \"rotation\": [w,x,y,z]}, ...]}
a pose may give \"basis\": [I, J, K] (column vectors) instead of \"rotation\"; optional
\"times\": [T0, ...] and \"velocities\": [V0 or null, ...] as --times / --velocities.
Quaternions are [w, x, y, z], scalar first; angles in radians; frames right-handed.
"
    };
}

/// The example that ends the overview.
macro_rules! example {
    () => {
        "\
EXAMPLE:
  screwbender preset l_cycle_rotated | screwbender subdivide --scheme jarek --levels 3
"
    };
}

/// What a glTF export holds, for the overview and `export --help`.
macro_rules! export_note {
    () => {
        "\
The glTF asset animates the object (the preset's shape, else a box; pip_morph5 morphs
between its shapes by morph targets) and an empty node 'control poses' whose keyframes are
the control poses; 'import' reads that node back.
"
    };
}

/// The CSV that `import` reads, for the overview and `import --help`.
macro_rules! csv_input {
    () => {
        "CSV input: x,y,z,qw,qx,qy,qz per line; optional header (any column order), '#' comments.\n"
    };
}

/// What `screwbender --help` (also `-h` and `help`) prints: every command with its options on
/// one page, which clap's generated list of commands would not give.
const HELP: &str = concat!(
    "\
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
                                                 decoupled kks se3bspline rb cc0 cc1; default: all
                                                 that apply; se3interp splitinterp barr if named)
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
  screwbender completions bash|zsh|fish          a shell completion script on stdout (also
                                                 elvish, powershell)
  screwbender man [COMMAND]                      the manual page (roff) on stdout
  screwbender COMMAND --help | help COMMAND      one command in full
  screwbender help | --help | --version

OPTIONS (subdivide, eval):
  --scheme bspline|fourpoint|jarek|j subdivision scheme (default: fourpoint)
  --s S                              the J_s family's parameter (S=0 4-point, S=0.5 Jarek, S=1
                                     B-spline; direct rules only): alone it selects the family,
                                     with --scheme it must agree with the scheme
  --rules direct|split               rule set: revised paper's direct rules (default) or the
                                     first version's split-then-tweak rules (also:
                                     split-then-tweak)
  --levels N                         subdivision steps, 0 to 19 (default 5; eval: 0 = plain
                                     polyscrew)
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
",
    export_note!(),
    "
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
",
    csv_input!(),
    "
",
    file_format!(),
    "
",
    example!()
);

/// `screwbender`: smooth rigid motions by screw subdivision (Powell & Rossignac).
#[derive(Parser)]
#[command(
    name = "screwbender",
    version,
    about = "Smooth rigid motions by screw subdivision (Powell & Rossignac)",
    long_about = "Smooth rigid motions by screw subdivision (Powell & Rossignac).\n\n\
        Reads a JSON motion document from FILE or standard input ('-') and writes JSON (or \
        CSV, glTF) to standard output. Exit status 0 on success, 2 with a one-line message on \
        standard error for bad usage or bad input.",
    after_long_help = concat!(file_format!(), "\n", example!()),
    override_help = HELP,
    // Help paragraphs wrap to the terminal, but not wider than they read well.
    max_term_width = 100,
    subcommand_required = true,
    // No command is a usage error (exit status 2), not a request for help.
    arg_required_else_help = false
)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The commands.
// Each lets a repeated option override itself (`--levels 3 --levels 4` is 4), so that a script
// can append to a set of default options.
#[derive(Subcommand)]
pub enum Command {
    /// Refined motion document on stdout
    ///
    /// Subdivides the control poses of FILE N times (--levels N) and writes the refined poses
    /// as a motion document (the same 'closed', and the document's name).
    #[command(
        args_override_self = true,
        after_long_help = concat!(file_format!(), "\n", example!())
    )]
    Subdivide(SubdivideArgs),
    /// Poses of the motion at coarse parameters U
    ///
    /// Evaluates the subdivided motion (with --levels 0: the plain polyscrew) at each coarse
    /// parameter U (pose i of FILE is at U = i) and writes the poses as JSON, one per line.
    #[command(args_override_self = true, after_long_help = file_format!())]
    Eval(EvalArgs),
    /// screw(p0, T, p1) for a document of two poses
    ///
    /// The screw motion from the first pose of FILE to the second (its axis, angle, slide,
    /// pitch), and its poses at each T (T = 0: the first pose, T = 1: the second).
    #[command(args_override_self = true, after_long_help = file_format!())]
    Screw(ScrewArgs),
    /// List presets, or print preset ID as a document
    #[command(args_override_self = true)]
    Preset(PresetArgs),
    /// Metrics of the comparison methods on the poses
    ///
    /// Builds each comparison method's motion through the poses of FILE (pose i at parameter
    /// u = i; a closed input is a cycle) and prints their metrics as an aligned table, or JSON.
    /// A motion that is poor though it was built gets a note in its row and a
    /// 'screwbender: warning: METHOD: …' line on standard error.
    #[command(args_override_self = true, after_long_help = file_format!())]
    Compare(CompareArgs),
    /// The Chaudhry–Cameron motion's rational Bézier control points (JSON)
    ///
    /// Fits the Chaudhry–Cameron rational motion to the poses of FILE (at the document's times,
    /// else 1 s per span) or, with --triangles, to a raw triangle sequence, and writes its
    /// rational Bézier control points as JSON. A C1 fit whose recursion runs away gets a
    /// 'screwbender: warning: …' line on standard error.
    #[command(args_override_self = true, after_long_help = file_format!())]
    Rational(RationalArgs),
    /// The motion as a glTF 2.0 asset or CSV samples
    ///
    /// Writes the subdivided motion of FILE as a glTF 2.0 asset (OUT.glb, or OUT.gltf +
    /// OUT.bin) or as CSV samples (to standard output without -o). Keyframes are adaptive (the
    /// linear interpolation between them stays within --tolerance of the motion) or at a fixed
    /// rate (--fps).
    #[command(
        args_override_self = true,
        after_long_help = concat!(export_note!(), "\n", file_format!())
    )]
    Export(ExportArgs),
    /// Control poses as a motion document
    ///
    /// Reads control poses from a glTF asset (.glb, .gltf), a CSV file or a motion document
    /// (.json) and writes them as a motion document. A file of many poses (samples rather than
    /// keys) gets a note on standard error; --reduce keeps fewer.
    // FILE is checked by `import` itself, to say which files it reads.
    #[command(
        args_override_self = true,
        override_usage = "screwbender import [OPTIONS] FILE",
        after_long_help = csv_input!()
    )]
    Import(ImportArgs),
    /// A smooth motion fitted to many measured poses
    ///
    /// Reads timestamped poses (a glTF animation, a CSV file or a motion document) and writes
    /// the control poses of the open motion (--method) that passes closest to them, as a motion
    /// document, with a report of the residuals (RMS and largest distance, angle and deviation).
    /// With -o the report goes to standard output, else to standard error.
    #[command(
        args_override_self = true,
        override_usage = "screwbender fit [OPTIONS] FILE (--controls N | --tolerance T)",
        after_long_help = csv_input!()
    )]
    Fit(FitArgs),
    /// A shell completion script on stdout
    ///
    /// Prints the completion script for SHELL, e.g. for bash:
    ///   screwbender completions bash > ~/.local/share/bash-completion/completions/screwbender
    /// for zsh, into a file '_screwbender' in a directory of $fpath; for fish:
    ///   screwbender completions fish > ~/.config/fish/completions/screwbender.fish
    #[command(verbatim_doc_comment)]
    Completions {
        /// The shell: bash, zsh, fish (also elvish, powershell)
        #[arg(value_name = "SHELL")]
        shell: Shell,
    },
    /// The manual page (roff) on stdout
    ///
    /// Prints screwbender's manual page in roff, or with COMMAND the page of that command
    /// (screwbender-COMMAND), e.g. 'screwbender man | man -l -' to read it, or
    /// 'screwbender man compare > screwbender-compare.1' to install one.
    Man {
        /// A command whose page to print instead (default: the page of screwbender)
        #[arg(value_name = "COMMAND")]
        command: Option<String>,
    },
}

/// `screwbender subdivide`.
#[derive(clap::Args)]
pub struct SubdivideArgs {
    /// JSON motion document (default: standard input, also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    // Last: the subdivision options' help heading would also take the options after them.
    /// The subdivision options.
    #[command(flatten)]
    pub sub: SubdivisionArgs,
}

/// `screwbender eval`.
#[derive(clap::Args)]
pub struct EvalArgs {
    /// A coarse parameter to evaluate the motion at (pose i at U = i); repeat for more
    #[arg(long = "u", value_name = "U", value_parser = Finite, allow_hyphen_values = true)]
    pub us: Vec<f64>,
    /// JSON motion document (default: standard input, also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    // Last: the subdivision options' help heading would also take the options after them.
    /// The subdivision options.
    #[command(flatten)]
    pub sub: SubdivisionArgs,
}

/// `screwbender screw`.
#[derive(clap::Args)]
pub struct ScrewArgs {
    /// A screw parameter (0: the first pose, 1: the second); repeat for more
    #[arg(long = "t", value_name = "T", value_parser = Finite, allow_hyphen_values = true)]
    pub ts: Vec<f64>,
    /// JSON motion document (default: standard input, also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
}

/// `screwbender preset`.
#[derive(clap::Args)]
pub struct PresetArgs {
    /// The preset to print as a motion document (without: the list of presets)
    #[arg(value_name = "ID")]
    pub id: Option<String>,
}

/// `screwbender compare`.
#[derive(clap::Args)]
pub struct CompareArgs {
    /// Methods to compare, comma-separated or repeated: polyscrew bspline fourpoint jarek slerp
    /// decoupled kks se3bspline rb cc0 cc1; only when named: se3interp splitinterp (the
    /// interpolating Lie-group B-splines) and barr (the discrete baseline's objective beside
    /// rb's; open poses only); default: all that apply
    #[arg(long, value_name = "A,B,...", allow_hyphen_values = true)]
    pub methods: Vec<String>,
    /// The metrics as JSON instead of a table
    #[arg(long)]
    pub json: bool,
    /// Treat the poses as an open sequence (overrides the document's 'closed')
    #[arg(long)]
    pub open: bool,
    /// JSON motion document (default: standard input, also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
}

/// `screwbender rational`.
#[derive(clap::Args)]
pub struct RationalArgs {
    /// Continuity of the fit: c0 or c1 (default: c1)
    #[arg(long, value_name = "c0|c1", allow_hyphen_values = true)]
    pub continuity: Option<String>,
    /// The C1 fit's end condition: 18 (zero curvature at the start, the default) or 19 (at the
    /// end)
    #[arg(long, value_name = "18|19", allow_hyphen_values = true)]
    pub end: Option<String>,
    /// Read a raw triangle sequence instead of a motion document: one key per line, t then the
    /// vertices a, x, y (10 numbers separated by commas or spaces; '#' comments)
    #[arg(long)]
    pub triangles: bool,
    /// With --triangles: a closed motion, back at the first key at time T (after the last
    /// key's; C0 only)
    #[arg(long, value_name = "T", value_parser = Finite, allow_hyphen_values = true)]
    pub closing_time: Option<f64>,
    /// A motion document, or with --triangles the triangle sequence (default: standard input,
    /// also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
}

/// `screwbender export`.
#[derive(clap::Args)]
pub struct ExportArgs {
    /// Output format: glb, gltf (OUT.gltf + OUT.bin) or csv (required)
    #[arg(long, value_name = "glb|gltf|csv", allow_hyphen_values = true)]
    pub format: Option<String>,
    /// Adaptive keyframes: linear interpolation stays within T of the motion (default 1e-4
    /// scene units); the keyframe count adapts per screw span
    #[arg(long, value_name = "T", value_parser = Finite, allow_hyphen_values = true)]
    pub tolerance: Option<f64>,
    /// Fixed-rate keyframes instead (F per second)
    #[arg(long, value_name = "F", value_parser = Finite, allow_hyphen_values = true)]
    pub fps: Option<f64>,
    /// Time of each control pose (a cycle also gives the time pose 0 returns); default: the
    /// document's own times, else 1 s per control span
    #[arg(long, value_name = "T0,T1,...", allow_hyphen_values = true)]
    pub times: Option<String>,
    /// Rate of the motion parameter at each control pose (poses per second, >= 0), '-' for a
    /// free key (e.g. -,0.5,-); default: the document's own
    #[arg(long, value_name = "V0,V1,...", allow_hyphen_values = true)]
    pub velocities: Option<String>,
    /// The tolerance holds at object points up to R from its origin (default: the preset's
    /// mesh, else the placeholder box)
    #[arg(long, value_name = "R", value_parser = Finite, allow_hyphen_values = true)]
    pub radius: Option<f64>,
    /// csv: trajectory t,u,x,y,z of this body point (default: poses t,u,x,y,z,qw,qx,qy,qz)
    #[arg(long, value_name = "x,y,z", allow_hyphen_values = true)]
    pub point: Option<String>,
    /// glb/gltf: also one empty node per control pose
    #[arg(long)]
    pub control_nodes: bool,
    /// One summary line (sample count) on standard error
    #[arg(long, short)]
    pub verbose: bool,
    /// Where to write: OUT.glb, OUT.gltf + OUT.bin, or the CSV (default: standard output)
    #[arg(long, short, value_name = "OUT", allow_hyphen_values = true)]
    pub output: Option<String>,
    /// JSON motion document (default: standard input, also '-')
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    // Last: the subdivision options' help heading would also take the options after them.
    /// The subdivision options.
    #[command(flatten)]
    pub sub: SubdivisionArgs,
}

/// `screwbender import`.
#[derive(clap::Args)]
pub struct ImportArgs {
    /// The file to read: .glb, .gltf, .csv or .json (required)
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    /// The animated node whose keyframes are the poses (default: 'control poses' if present,
    /// else the first animated node)
    #[arg(
        long,
        value_name = "NAME",
        overrides_with = "nodes",
        allow_hyphen_values = true
    )]
    pub node: Option<String>,
    /// The static transforms of these nodes instead
    #[arg(
        long,
        value_name = "A,B,...",
        overrides_with = "node",
        allow_hyphen_values = true
    )]
    pub nodes: Option<String>,
    /// An open sequence (default: a cycle when the last pose repeats the first)
    #[arg(long)]
    pub open: bool,
    /// Write the document to OUT instead of standard output
    #[arg(long, short, value_name = "OUT", allow_hyphen_values = true)]
    pub output: Option<String>,
    /// The pose count kept on standard error
    #[arg(long, short)]
    pub verbose: bool,
    /// every:K keeps every K-th pose (for dense keyframes, e.g. a sampled CSV); fit:TOL (or
    /// fit:TOL:RADIUS) keeps the fewest poses whose polyscrew stays within TOL of the given poses
    /// (at points up to RADIUS from the origin; default 0: the origin)
    #[arg(
        long,
        value_name = "every:K|fit:TOL[:RADIUS]",
        allow_hyphen_values = true
    )]
    pub reduce: Option<String>,
}

/// `screwbender fit`.
#[derive(clap::Args)]
pub struct FitArgs {
    /// The file of measured poses: .glb, .gltf, .csv or .json (required)
    #[arg(value_name = "FILE")]
    pub file: Option<String>,
    /// The motion fitted: screwbender (the cubic B-spline scheme) or se3bspline (the
    /// cumulative B-spline on SE(3))
    #[arg(long, value_name = "METHOD", default_value = "screwbender")]
    pub method: String,
    /// This many control poses
    #[arg(long, value_name = "N", conflicts_with = "tolerance")]
    pub controls: Option<usize>,
    /// As few control poses as keep the RMS deviation (distance + radius × angle) within T
    #[arg(long, value_name = "T", value_parser = Finite)]
    pub tolerance: Option<f64>,
    /// Weight of the smoothness term (0: none)
    #[arg(long, value_name = "W", default_value_t = 0.0, value_parser = Finite)]
    pub smoothness: f64,
    /// Robust loss against outliers: none, huber or cauchy
    #[arg(long, value_name = "LOSS", default_value = "none")]
    pub robust: String,
    /// Length that weighs angles against distances: the body's extent around its origin
    #[arg(long, value_name = "R", default_value_t = 1.0, value_parser = Finite)]
    pub radius: f64,
    /// The report as JSON
    #[arg(long)]
    pub json: bool,
    /// Write the document to OUT instead of standard output
    #[arg(long, short, value_name = "OUT", allow_hyphen_values = true)]
    pub output: Option<String>,
    /// Fit nothing: report how far the motion of the document MOTION (its control poses and
    /// key times, as a fit writes them) is from FILE's poses
    #[arg(long, value_name = "MOTION", conflicts_with_all = ["controls", "tolerance", "smoothness", "robust", "output"])]
    pub measure: Option<String>,
}

/// The whole command line as clap sees it (for parsing, completion scripts and the man page).
pub fn command() -> clap::Command {
    Cli::command()
}

/// What the command line asks for.
pub enum Parsed {
    /// Run this command.
    Run(Box<Command>),
    /// Print this text and exit with status 0 (`--help`, `--version`).
    Print(String),
}

/// Parses the command line (`args` with the program name first).
pub fn parse(args: Vec<OsString>) -> Result<Parsed, Failure> {
    // The command's name, for pointing at its own help in a usage error.
    let name = args
        .get(1)
        .and_then(|a| a.to_str())
        .filter(|a| command().find_subcommand(a).is_some())
        .map(str::to_string);
    // An option missing its value is the last argument, as typed (`-o` rather than
    // `--output`).
    let last = args
        .last()
        .and_then(|a| a.to_str())
        .and_then(|a| a.split('=').next())
        .map(str::to_string);
    let matches = command().try_get_matches_from(args);
    match matches.and_then(|m| Cli::from_arg_matches(&m)) {
        Ok(cli) => Ok(Parsed::Run(Box::new(cli.command))),
        Err(e) => match e.kind() {
            ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
                Ok(Parsed::Print(e.render().to_string()))
            }
            _ => Err(Failure(usage_error(&e, name.as_deref(), last.as_deref()))),
        },
    }
}

/// One line for a usage error found by clap: in the words of the CLI's other messages
/// (`unknown option '--x'`, `--levels needs a value`) where it has such words, so that a script
/// matching them keeps working, else clap's own first line; both point at the command's help.
fn usage_error(e: &clap::Error, command_name: Option<&str>, last: Option<&str>) -> String {
    let context = |kind| match e.get(kind) {
        Some(ContextValue::String(s)) => Some(s.as_str()),
        _ => None,
    };
    let try_help = match command_name {
        Some(c) => format!("try 'screwbender {c} --help'"),
        None => "try 'screwbender --help'".to_string(),
    };
    // An argument as clap names it ("--levels <N>", "<SHELL>"): the option, or the value's
    // name.
    let arg_name = |arg: &str| {
        let first = arg.split_whitespace().next().unwrap_or(arg);
        first.trim_matches(|c| c == '<' || c == '>').to_string()
    };
    match (e.kind(), context(ContextKind::InvalidArg)) {
        (ErrorKind::UnknownArgument, Some(arg)) if arg.starts_with('-') => {
            format!("unknown option '{arg}' ({try_help})")
        }
        (ErrorKind::UnknownArgument, Some(arg)) => {
            // A second FILE (or ID): name what the command takes one of.
            let one = command_name
                .and_then(|c| command().find_subcommand(c).cloned())
                .and_then(|c| {
                    c.get_positionals()
                        .find_map(|p| p.get_value_names().and_then(|n| n.first().cloned()))
                });
            match one {
                Some(one) => format!("more than one {one} given ('{arg}'; {try_help})"),
                None => format!("unexpected argument '{arg}' ({try_help})"),
            }
        }
        (ErrorKind::MissingRequiredArgument, _) => {
            let missing = match e.get(ContextKind::InvalidArg) {
                Some(ContextValue::Strings(names)) => {
                    names.iter().map(|n| arg_name(n)).collect::<Vec<_>>()
                }
                _ => Vec::new(),
            };
            format!("missing {} ({try_help})", missing.join(", "))
        }
        (ErrorKind::InvalidValue, Some(arg)) => {
            let name = arg_name(arg);
            match context(ContextKind::InvalidValue) {
                Some("") | None => match last {
                    Some(typed) if typed.starts_with('-') => format!("{typed} needs a value"),
                    _ => format!("{name} needs a value"),
                },
                Some(value) => {
                    let valid = match e.get(ContextKind::ValidValue) {
                        Some(ContextValue::Strings(v)) => format!(" (expected {})", v.join(", ")),
                        _ => String::new(),
                    };
                    format!("{name}: unknown value '{value}'{valid}")
                }
            }
        }
        (ErrorKind::InvalidSubcommand, _) => {
            let given = context(ContextKind::InvalidSubcommand).unwrap_or("");
            let names: Vec<String> = command()
                .get_subcommands()
                .map(|c| c.get_name().to_string())
                .collect();
            format!(
                "unknown command '{given}' (expected {}; try 'screwbender --help')",
                names.join(", ")
            )
        }
        (ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand, _) => {
            "no command given (try 'screwbender --help')".into()
        }
        (kind, _) => {
            let text = e.render().to_string();
            let line = text.lines().next().unwrap_or("bad usage");
            let line = line.strip_prefix("error: ").unwrap_or(line);
            // A value refused by the CLI's own checks ([`Finite`]) is its message alone.
            if kind == ErrorKind::ValueValidation {
                line.to_string()
            } else {
                format!("{line} ({try_help})")
            }
        }
    }
}
