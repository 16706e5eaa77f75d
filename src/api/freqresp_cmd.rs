//! `freqresp FILE`, continuous or sampled: one command path over [`super::float_cmds::freqresp`]
//! (the float response $C(zI - A)^{-1}B + D$ at $z = j\omega$, or $z = e^{j\omega T}$ for a
//! system file with a sample time `dt`) and the Bode plots of [`super::plots`] and
//! [`super::discrete_plots`].

use super::Failure;
use super::float_cmds::freqresp;
use crate::field::Field;
use std::path::Path;

/// `freqresp FILE`: on $j\omega$ for a continuous-time system (the range frames its poles and
/// zeros unless `--from`/`--to` are given), on the unit circle up to the Nyquist frequency
/// $1/(2T)$ for a sampled one (`dt` in the file); `--csv` and `--svg` as asked. One path for
/// both: only the range, the evaluation point and the plot differ.
pub(crate) fn freqresp_command<K: Field>(
    cmd: &super::Command,
    f: &crate::io::SystemFile,
    t: &crate::io::TypedSystem<K>,
    path: &Path,
) -> Result<super::Outcome, Failure> {
    let super::Command::Freqresp {
        from,
        to,
        points,
        svg,
        csv,
        ..
    } = cmd
    else {
        return Err(Failure::verification("internal: not freqresp".into()));
    };
    let (_, ins, outs) = super::plots::names(f, path, t.ss.ninputs(), t.ss.noutputs());
    let names = (ins.as_slice(), outs.as_slice());
    let csv = csv.as_deref();
    let Some(dt) = f.signals.dt.as_ref() else {
        let (from, to) = super::plots::bode_range(t, path, *from, *to)?;
        let r = freqresp(t, path, names, (from, to, *points), csv, None)?;
        if let Some(out) = svg {
            super::plots::bode_file(f, t, path, (from, to, *points), out)?;
        }
        return Ok(super::Outcome::plain(r));
    };
    let seconds = crate::field::rational_to_f64(dt);
    let nyquist = 0.5 / seconds;
    let range = (
        from.unwrap_or(nyquist / 1000.0),
        to.unwrap_or(nyquist),
        *points,
    );
    let mut r = freqresp(t, path, names, range, csv, Some(seconds))?;
    if let Some(out) = svg {
        super::discrete_plots::bode_file_dt(f, t, path, dt, range, out)?;
        r = r.str("svg", out.display().to_string());
    }
    Ok(super::Outcome::plain(r.rational("dt", dt).str(
        "note",
        "G(e^(j 2 pi f T)), up to the Nyquist frequency 1/(2 T) Hz",
    )))
}
