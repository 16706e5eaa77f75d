//! Reports of the discrete-time commands: exact stability (factors of $\det(zI - A)$ and
//! where their roots lie), exact step/impulse sequences, and c2d/d2c results.

use crate::field::{Field, Rational};
use crate::matrix::Matrix;
use crate::report::display::fmt_rational;
use crate::report::{Report, Value};
use crate::system::StateSpace;
use crate::system::discrete::stability::{Domain, Place, Stability, Verdict};

/// How the `stability` verdict was decided, in words, over the field of the factors (`QQ`
/// shown as `Q`); with a factor of non-real coefficients the conjugates it takes.
fn stability_method<F: Field>(s: &Stability<F>) -> String {
    let k = s.charpoly.field();
    let name = k.to_string();
    let name = name.strip_prefix('Q').unwrap_or(&name);
    let mut text = match s.domain {
        Domain::Discrete => format!(
            "exact over {name}: Schur-Cohn (Jury) reduction per irreducible factor; self-reciprocal factors counted on the circle by a Sturm sequence of h(z + 1/z)"
        ),
        Domain::Continuous => format!(
            "exact over {name}: each factor mapped by s = (z - 1)/(z + 1) onto the unit disk, then Schur-Cohn (Jury) and Sturm"
        ),
    };
    let non_real = s.factors.iter().any(|(f, ..)| {
        f.coeffs()
            .iter()
            .any(|c| k.conj(c).is_some_and(|b| b != *c))
    });
    if non_real {
        text.push_str("; a factor with non-real coefficients: |a| compared as a conj(a), p* = z^n conj(p)(1/z), on the circle through f conj(f) (real coefficients)");
    }
    text
}

/// The `stability` report: verdict, region, and per irreducible factor of the
/// characteristic polynomial its multiplicities and where its roots lie.
pub fn stability_report<F: Field>(s: &Stability<F>, dt: Option<&Rational>) -> Report {
    let (var, region, boundary) = match s.domain {
        Domain::Continuous => ("s", "Re s < 0", "imaginary axis"),
        Domain::Discrete => ("z", "|z| < 1", "unit circle"),
    };
    let verdict = match s.verdict {
        Verdict::AsymptoticallyStable => {
            format!("asymptotically stable (every eigenvalue in {region})")
        }
        Verdict::MarginallyStable => format!(
            "marginally stable (eigenvalues on the {boundary}, all semisimple; the others in {region})"
        ),
        Verdict::Unstable => format!("unstable (an eigenvalue outside the closed region {region})"),
        Verdict::UnstableJordan => {
            format!("unstable (a Jordan block larger than 1 on the {boundary})")
        }
    };
    let rows: Vec<Vec<String>> = s
        .factors
        .iter()
        .map(|(f, e, mu, place)| {
            let at = match place {
                Place::Inside => format!("inside ({region})"),
                Place::Boundary => format!("on the {boundary}"),
                Place::Outside => "a root outside".to_string(),
            };
            vec![f.to_string_var(var), e.to_string(), mu.to_string(), at]
        })
        .collect();
    let data = Value::List(
        rows.iter()
            .map(|r| Value::List(r.iter().map(|x| Value::Str(x.clone())).collect()))
            .collect(),
    );
    let header = ["factor", "in det", "in minpoly", "roots"]
        .map(String::from)
        .to_vec();
    let mut r = Report::titled("stability (exact)").str(
        "time",
        match s.domain {
            Domain::Continuous => "continuous",
            Domain::Discrete => "discrete",
        },
    );
    if let Some(dt) = dt {
        r = r.rational("dt", dt);
    }
    r.str("verdict", verdict)
        .bool(
            "asymptotically_stable",
            s.verdict == Verdict::AsymptoticallyStable,
        )
        .str("charpoly", s.charpoly.to_string_var(var))
        .with("factors", Value::table(data, header, rows))
        .str("method", stability_method(s))
        .bool("verified", true)
}

/// Samples shown exactly in text (JSON holds every sample).
const SHOWN: usize = 12;

/// An exact sequence report: per sample $k$ (time $k T$) the $p \times m$ matrix of
/// values as exact strings; the text shows the first [`SHOWN`] samples as a table, one
/// column per channel `input -> output`.
pub fn sequence_report<K: Field>(
    what: &str,
    dt: &Rational,
    seq: &[Matrix<K>],
    (inputs, outputs): (&[String], &[String]),
) -> Report {
    let k = seq.first().map(|m| m.field().clone());
    let show = |x: &K::Elem| k.as_ref().map_or(String::new(), |k| k.fmt_elem(x));
    let exact: Vec<Value> = seq
        .iter()
        .map(|m| {
            Value::List(
                (0..m.nrows())
                    .map(|i| Value::List(m.row(i).iter().map(|x| Value::Str(show(x))).collect()))
                    .collect(),
            )
        })
        .collect();
    let mut header = vec!["k".to_string(), "t = k dt".to_string()];
    for o in outputs {
        for i in inputs {
            header.push(format!("{i} -> {o}"));
        }
    }
    let rows: Vec<Vec<String>> = seq
        .iter()
        .take(SHOWN)
        .enumerate()
        .map(|(n, m)| {
            let t = dt * Rational::from_integer(n.into());
            let mut row = vec![n.to_string(), fmt_rational(&t)];
            for i in 0..m.nrows() {
                row.extend(m.row(i).iter().map(|x| cell(k.as_ref(), x, show(x))));
            }
            row
        })
        .collect();
    let first = Value::List(exact.iter().take(SHOWN).cloned().collect());
    let shown = Value::table(first, header, rows);
    Report::titled(format!("{what} (discrete time, exact)"))
        .rational("dt", dt)
        .int("samples", seq.len())
        .list(
            "inputs",
            inputs.iter().map(|x| Value::Str(x.clone())).collect(),
        )
        .list(
            "outputs",
            outputs.iter().map(|x| Value::Str(x.clone())).collect(),
        )
        .with("first_samples", shown)
        .with("exact", Value::hidden_in_text(Value::List(exact)))
}

/// A table cell: the exact value, or `~` and its approximation when the exact text is
/// longer than 40 characters (JSON keeps it exact).
fn cell<K: Field>(k: Option<&K>, x: &K::Elem, exact: String) -> String {
    if exact.len() <= 40 {
        return exact;
    }
    match k.and_then(|k| k.approx(x)) {
        Some((re, _)) => format!("~{}", crate::report::text::short(re)),
        None => format!("{}...", &exact[..37]),
    }
}

/// The report of `c2d` / `d2c`: the method, the sample time, the system and its check.
pub fn conversion_report<K: Field>(
    title: &str,
    method: &str,
    dt: &Rational,
    sys: &StateSpace<K>,
    check: Option<(&str, bool)>,
) -> Report {
    let mut r = Report::titled(title.to_string())
        .str("method", method)
        .rational("dt", dt)
        .matrix("A", &sys.a)
        .matrix("B", &sys.b)
        .matrix("C", &sys.c)
        .matrix("D", &sys.d);
    if let Some((what, ok)) = check {
        r = r.str("check", what).bool("verified", ok);
    }
    r
}
