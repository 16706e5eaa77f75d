//! Option types of the command line shared by several subcommands: `--method`, `linalg`
//! operations, `poly` subcommands, the time-response options of `step` and `impulse`.

use clap::{Subcommand, ValueEnum};
use std::path::PathBuf;

/// `--method` of `minreal`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    Kalman,
    Rosenbrock,
    HoKalman,
    Jordan,
    Era,
}

impl MethodArg {
    /// The method `--method` names `name` (`kalman`, `rosenbrock`, `ho-kalman`, `jordan`,
    /// `era`), as the command line parses it; the message lists the names otherwise.
    ///
    /// # Errors
    /// An unknown name.
    ///
    /// ```
    /// use exactlti::api::MethodArg;
    /// assert_eq!(MethodArg::named("ho-kalman"), Ok(MethodArg::HoKalman));
    /// assert!(MethodArg::named("magic").unwrap_err().contains("kalman, rosenbrock"));
    /// ```
    pub fn named(name: &str) -> Result<MethodArg, String> {
        <MethodArg as ValueEnum>::from_str(name, false).map_err(|_| {
            let names: Vec<String> = MethodArg::value_variants()
                .iter()
                .filter_map(|v| v.to_possible_value().map(|p| p.get_name().to_string()))
                .collect();
            format!("unknown method '{name}' ({})", names.join(", "))
        })
    }

    /// The exact minimal-realization method (`None` for `era`, the float path).
    pub fn exact(self) -> Option<crate::realization::MinrealMethod> {
        use crate::realization::MinrealMethod as M;
        match self {
            MethodArg::Kalman => Some(M::Kalman),
            MethodArg::Rosenbrock => Some(M::Rosenbrock),
            MethodArg::HoKalman => Some(M::HoKalman),
            MethodArg::Jordan => Some(M::Jordan),
            MethodArg::Era => None,
        }
    }
}

/// Operations of `linalg`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum LinalgOp {
    Rank,
    Det,
    Charpoly,
    Minpoly,
    Inverse,
    Nullspace,
    Rref,
}

/// Operations of `poly`.
#[derive(Subcommand, Debug, Clone)]
pub enum PolyCmd {
    /// Factorization over Q into irreducibles with multiplicities (uni- or multivariate).
    Factor {
        /// A polynomial, e.g. "-4*x^3 + 1" or "x^2*y - y" (may start with '-').
        #[arg(allow_hyphen_values = true, value_name = "EXPR")]
        expr: String,
    },
    /// Greatest common divisor of two (multivariate) polynomials over Q, with cofactors.
    Gcd {
        /// First polynomial (may start with '-').
        #[arg(allow_hyphen_values = true, value_name = "EXPR")]
        f: String,
        /// Second polynomial (may start with '-').
        #[arg(allow_hyphen_values = true, value_name = "EXPR")]
        g: String,
    },
    /// All complex roots, certified, as exact algebraic numbers.
    Roots {
        /// A polynomial in one variable, e.g. "-x^2 + 2" (may start with '-').
        #[arg(allow_hyphen_values = true, value_name = "EXPR")]
        expr: String,
        /// Correct significant digits of the displayed approximations (1 to 200).
        #[arg(long, default_value_t = 10)]
        digits: usize,
    },
}

/// Options shared by `step` and `impulse`.
#[derive(clap::Args, Debug, Clone)]
pub struct TimeOpts {
    /// End time in seconds (default: about 7 time constants of the slowest pole, rounded
    /// up to 1, 2 or 5 x 10^k).
    #[arg(long, value_name = "SECONDS")]
    pub to: Option<f64>,
    /// Number of evenly spaced times from 0 to --to (2 to 100000; default: 20 per period
    /// of the fastest mode, 500 to 5000).
    #[arg(long, value_name = "N")]
    pub points: Option<usize>,
    /// Write the plot (one panel per channel, names from the file) as SVG.
    #[arg(long, value_name = "OUT.svg")]
    pub svg: Option<PathBuf>,
    /// Write the values as CSV (time, then one column per input -> output channel).
    #[arg(long, value_name = "OUT.csv")]
    pub csv: Option<PathBuf>,
    /// Float only (matrix exponential), also for a rational system.
    #[arg(long)]
    pub float: bool,
}

/// Largest `--digits` of `poly roots` and `critical`: the certified refinement costs about
/// the cube of the digits (bicycle, `critical`: 200 digits 1.2 s, 1000 digits 38 s).
pub const MAX_DIGITS: usize = 200;
