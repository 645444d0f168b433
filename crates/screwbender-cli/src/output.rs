//! What a command writes, and writing it: a command that succeeded hands back an [`Output`],
//! which writes its text through a buffer as it produces it, so a large result (a refined
//! document of 2^20 poses, a long evaluation) never exists as one string.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::process::ExitCode;

use crate::failure::Failure;

/// Size of the buffer between an [`Output`] and its file or standard output.
const BUFFER_BYTES: usize = 1 << 16;

/// Writes a command's output to the writer it is given.
type WriteFn = Box<dyn FnOnce(&mut dyn Write) -> io::Result<()>>;

/// A command's output, written once the command has succeeded (its errors come before).
pub struct Output(WriteFn);

impl Output {
    /// Output that is already text.
    pub fn text(text: String) -> Output {
        Output::writer(move |w| w.write_all(text.as_bytes()))
    }

    /// Output written by `write` when it is written.
    pub fn writer(write: impl FnOnce(&mut dyn Write) -> io::Result<()> + 'static) -> Output {
        Output(Box::new(write))
    }

    /// Writes the output to standard output: exit status 0, also when the reader stops early
    /// (`screwbender subdivide … | head`), else 2 with a message.
    pub fn write_stdout(self) -> ExitCode {
        let mut stdout = BufWriter::with_capacity(BUFFER_BYTES, io::stdout().lock());
        // `print!` would panic on a broken pipe: write explicitly and stop quietly.
        match (self.0)(&mut stdout).and_then(|()| stdout.flush()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                // What is still buffered has nowhere to go: drop it without writing again.
                let (_, _) = stdout.into_parts();
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("screwbender: standard output: {e}");
                ExitCode::from(2)
            }
        }
    }

    /// Writes the output to the file `path` (created or truncated); failures name the file.
    pub fn write_file(self, path: &str) -> Result<(), Failure> {
        let fail = |e: io::Error| Failure(format!("{path}: {e}"));
        let mut file = BufWriter::with_capacity(BUFFER_BYTES, File::create(path).map_err(fail)?);
        (self.0)(&mut file)
            .and_then(|()| file.flush())
            .map_err(fail)
    }
}
