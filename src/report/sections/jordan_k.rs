//! Report of the Jordan form over a quadratic field ([`crate::jordan::over_k`]): the same
//! contract keys as the rational report (`eigenvalues`, `J`, `T`, `verified`, plus `n`,
//! `field`, `charpoly`, `presentation`, `symbols`).

use super::eigenvalue_items;
use crate::field::Field;
use crate::jordan::fmt_approx;
use crate::jordan::over_k::JordanFormK;
use crate::report::{MatrixOut, Report, Value};

impl JordanFormK {
    /// $J$ and $T$ for output: per eigenvalue, entries exact in its field $E$ at that root.
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        let n = self.n();
        let zero_s = || vec![vec!["0".to_string(); n]; n];
        let zero_a = || vec![vec![(0.0, 0.0); n]; n];
        let (mut je, mut ja, mut te, mut ta) = (zero_s(), zero_a(), zero_s(), zero_a());
        let mut off = 0;
        for (f, v, j) in self.root_columns() {
            let m = v.ncols();
            for r in 0..n {
                for q in 0..m {
                    te[r][off + q] = f.fmt_elem(v.get(r, q));
                    ta[r][off + q] = f.approx(v.get(r, q));
                }
            }
            for r in 0..m {
                for q in 0..m {
                    je[off + r][off + q] = f.fmt_elem(j.get(r, q));
                    ja[off + r][off + q] = f.approx(j.get(r, q));
                }
            }
            off += m;
        }
        (MatrixOut::from_parts(je, ja), MatrixOut::from_parts(te, ta))
    }
    /// The report with the CLI contract's keys (those of the rational Jordan report).
    pub fn report(&self) -> Report {
        let k = self.base();
        let single = self.single_field();
        let presentation = if single.is_some() {
            format!("single matrix over {k}")
        } else {
            format!(
                "per eigenvalue: the columns of eigenvalue r<k> are exact in {k}(r<k>), written \
                 as polynomials in r<k> over {k} (with the radical for a rational quadratic \
                 factor)"
            )
        };
        let symbols: Vec<Value> = self
            .eigenvalues
            .iter()
            .enumerate()
            .filter(|(_, e)| {
                let c = &self.components[e.component];
                c.factor.deg() >= 2 && !(c.factor.deg() == 2 && c.minpoly.deg() == 2)
            })
            .map(|(_, e)| {
                let c = &self.components[e.component];
                Value::Str(format!(
                    "{} = root of {} near {} (over {k}: root of {})",
                    e.symbol,
                    e.minpoly,
                    fmt_approx(e.approx),
                    c.factor
                ))
            })
            .collect();
        let (jo, to) = match single {
            Some((j, t)) => (MatrixOut::from_matrix(&j), MatrixOut::from_matrix(&t)),
            None => self.j_t_out(),
        };
        let mut r = Report::titled("Jordan form")
            .int("n", self.n())
            .str("field", k.to_string())
            .str("charpoly", self.charpoly.to_string())
            .list("eigenvalues", eigenvalue_items(&self.eigenvalues))
            .with("J", Value::Matrix(Box::new(jo)))
            .with("T", Value::Matrix(Box::new(to)))
            .str("presentation", presentation);
        if !symbols.is_empty() {
            r = r.list("symbols", symbols);
        }
        r.bool("verified", self.verified)
    }
}

impl std::fmt::Display for JordanFormK {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl crate::jordan::over_k::RealFormK {
    /// Report: `J`, `T` (exact texts and `_approx`), `exact`, `verified`, and for the compact
    /// form `presentation` and `symbols` (the keys of the rational real Jordan report).
    pub fn report(&self) -> Report {
        let cx = |m: &[Vec<f64>]| -> Vec<Vec<(f64, f64)>> {
            m.iter()
                .map(|r| r.iter().map(|&x| (x, 0.0)).collect())
                .collect()
        };
        let jo = MatrixOut::from_parts(self.j.clone(), cx(&self.j_approx));
        let to = MatrixOut::from_parts(self.t.clone(), cx(&self.t_approx));
        let mut r = Report::titled("Real Jordan form")
            .with("J", Value::Matrix(Box::new(jo)))
            .with("T", Value::Matrix(Box::new(to)))
            .bool("exact", true)
            .bool("verified", self.verified);
        if self.compact {
            r = r
                .str(
                    "presentation",
                    "compact: each complex pair r<k> = a<k> + b<k>*i has the block [[a, b], \
                     [-b, a]] and the columns Re v, Im v of its complex chains v (exact in \
                     K(r<k>)); verified on the complex side (A V = V J in K(r<k>), which \
                     implies A T = T J)",
                )
                .list(
                    "symbols",
                    self.symbols.iter().cloned().map(Value::Str).collect(),
                );
        }
        r
    }
}

/// Exact texts and approximations of a matrix under construction.
type Cells = (Vec<Vec<String>>, Vec<Vec<(f64, f64)>>);

impl crate::realization::JordanMinimalK {
    /// The CLI report: the keys of the rational Jordan-method report (`order`,
    /// `mcmillan_degree`, `stages`, `A`..`D`, `modes`, `symbols`, `verified`).
    pub fn report(&self) -> Report {
        let r = self.order();
        let (m, p) = (self.d.ncols(), self.d.nrows());
        let empty = |rows: usize, cols: usize| {
            (
                vec![vec!["0".to_string(); cols]; rows],
                vec![vec![(0.0, 0.0); cols]; rows],
            )
        };
        let (mut a, mut b, mut c) = (empty(r, r), empty(r, m), empty(p, r));
        let mut off = 0;
        for blk in &self.blocks {
            let f = &blk.field;
            let put = |o: &mut Cells, i: usize, j: usize, x: &crate::jordan::over_k::RelElem| {
                o.0[i][j] = f.fmt_elem(x);
                o.1[i][j] = f.approx(x);
            };
            let s = blk.a.nrows();
            for i in 0..s {
                for j in 0..s {
                    put(&mut a, off + i, off + j, blk.a.get(i, j));
                }
                for j in 0..m {
                    put(&mut b, off + i, j, blk.b.get(i, j));
                }
                for row in 0..p {
                    put(&mut c, row, off + i, blk.c.get(row, i));
                }
            }
            off += s;
        }
        let out = |x: Cells| Value::Matrix(Box::new(MatrixOut::from_parts(x.0, x.1)));
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .str("field", self.d.field().to_string())
            .int("original_order", self.stages[0])
            .int("order", r)
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&s| Value::Int(s as i64)).collect()),
            )
            .with("A", out(a))
            .with("B", out(b))
            .with("C", out(c))
            .matrix("D", &self.d)
            .with(
                "modes",
                crate::report::str_list(self.blocks.iter().map(|b| b.eigenvalue.clone())),
            )
            .str(
                "presentation",
                "complex modal form: one Jordan block group per eigenvalue r<k>, entries exact \
                 in K(r<k>)",
            )
            .with(
                "symbols",
                Value::List(
                    self.symbols
                        .iter()
                        .map(|(k, v)| Value::Str(format!("{k} = {v}")))
                        .collect(),
                ),
            )
            .bool("verified", self.verified)
    }
}
