//! The real Jordan form of a matrix over a real quadratic field $K = \mathbb{Q}(\sqrt d)$,
//! $d > 0$ (a real matrix).
//!
//! Every factor $g$ of $\chi_A$ over $K$ has real coefficients, so the non-real roots of
//! $g$ come in conjugate pairs within one component. A real root keeps its Jordan blocks and
//! its (real) columns. A pair $\theta = a + b i$, $\bar\theta$ ($b > 0$) gives, per Jordan
//! block of $\theta$ with chain $v_1, \dots, v_s$, the real block with diagonal blocks
//! $[[a, b], [-b, a]]$, $I_2$ above them, and the columns $\mathrm{Re}\, v_1, \mathrm{Im}\,
//! v_1, \dots$: from $A v = \theta v$, $A\,\mathrm{Re}\, v = a\,\mathrm{Re}\, v -
//! b\,\mathrm{Im}\, v$ and $A\,\mathrm{Im}\, v = b\,\mathrm{Re}\, v + a\,\mathrm{Im}\, v$.
//!
//! Presentation (the compact form of the rational real Jordan form): a pair's entries are
//! the real and imaginary parts of exact elements of $E = K(\theta)$, written `Re(x)`,
//! `Im(x)` with $a$, $b$ as `a<k>`, `b<k>`; for a rational quadratic factor with roots
//! $a_0 \pm s\sqrt f$ ($f < 0$) they are explicit: `u` and `v*sqrt(-f)`, $u, v \in K$.
//! Verification is on the complex side: $A V = V J_t$ holds exactly in $E$ (checked by
//! [`super::ComponentK::verify`]), which implies $A T_R = T_R J_R$.

use super::JordanFormK;
use crate::error::{Error, Result};
use crate::field::Field;

/// The real Jordan form over a real quadratic field, as exact entry texts and
/// approximations (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct RealFormK {
    pub n: usize,
    /// $J_R$ and $T_R$: exact texts.
    pub j: Vec<Vec<String>>,
    pub t: Vec<Vec<String>>,
    /// Their approximations.
    pub j_approx: Vec<Vec<f64>>,
    pub t_approx: Vec<Vec<f64>>,
    /// Definitions of the symbols `a<k>`, `b<k>`, `r<k>` used.
    pub symbols: Vec<String>,
    /// Some complex pair is written in the compact form.
    pub compact: bool,
    /// The complex form's identities held exactly (they imply the real ones).
    pub verified: bool,
}

impl JordanFormK {
    /// The real Jordan form (module [`self`] docs).
    ///
    /// # Errors
    /// `Invalid` when $K$ is not real (a matrix over $\mathbb{Q}(i)$ with a non-real entry
    /// has no real Jordan form).
    pub fn real_form(&self) -> Result<RealFormK> {
        let k = self.base();
        if !k.is_real() {
            return Err(Error::Invalid(format!(
                "A over {k} is not real, so it has no real Jordan form"
            )));
        }
        let n = self.n();
        let mut j = vec![vec!["0".to_string(); n]; n];
        let mut t = j.clone();
        let mut ja = vec![vec![0.0; n]; n];
        let mut ta = ja.clone();
        let (mut symbols, mut compact) = (vec![], false);
        let mut off = 0;
        for (ev, (f, v, jj)) in self.root_columns().into_iter().enumerate() {
            let e = &self.eigenvalues[ev];
            let m = v.ncols();
            if e.approx.1 == 0.0 || e.number.is_real() {
                for r in 0..n {
                    for q in 0..m {
                        t[r][off + q] = f.fmt_elem(v.get(r, q));
                        ta[r][off + q] = f.approx(v.get(r, q)).0;
                    }
                }
                for r in 0..m {
                    for q in 0..m {
                        j[off + r][off + q] = f.fmt_elem(jj.get(r, q));
                        ja[off + r][off + q] = f.approx(jj.get(r, q)).0;
                    }
                }
                off += m;
                continue;
            }
            if e.approx.1 < 0.0 {
                continue; // written with its upper partner
            }
            let radical = f.0.radical.clone();
            let (a_txt, b_txt) = match &radical {
                Some((a0, s, fd)) => (
                    crate::field::fmt_rational(a0),
                    crate::field::quadratic::fmt_pair(
                        &num_traits::Zero::zero(),
                        s,
                        &format!("sqrt({})", -fd),
                    ),
                ),
                None => {
                    compact = true;
                    let kk = &e.symbol[1..];
                    // a purely imaginary pair (proven by the isolation) has a = 0 exactly
                    let pure = e.number.is_pure_imaginary();
                    symbols.push(if pure {
                        format!(
                            "b{kk} = Im {0} (> 0, Re {0} = 0), {0} = {1}",
                            e.symbol, e.value
                        )
                    } else {
                        format!(
                            "a{kk} = Re {0}, b{kk} = Im {0} (> 0), {0} = {1}",
                            e.symbol, e.value
                        )
                    });
                    let a = if pure { "0".into() } else { format!("a{kk}") };
                    (a, format!("b{kk}"))
                }
            };
            let part = |x: &super::RelElem, imag: bool| -> (String, f64) {
                let (re, im) = f.approx(x);
                let val = if imag { im } else { re };
                let txt = match &radical {
                    // x = u + w sqrt(fd) = u + (w sqrt(-fd)) i, u, w in K (real)
                    Some((a0, s, fd)) => {
                        let kf = f.base();
                        let c0 = x.0.first().cloned().unwrap_or_else(|| kf.zero());
                        let c1 = x.0.get(1).cloned().unwrap_or_else(|| kf.zero());
                        if imag {
                            let w = kf.mul(&kf.from_rational(s), &c1);
                            if kf.is_zero(&w) {
                                "0".into()
                            } else {
                                let wt = kf.fmt_elem(&w);
                                let wt = if wt[1..].contains([' ', '+', '-']) {
                                    format!("({wt})")
                                } else {
                                    wt
                                };
                                format!("{wt}*sqrt({})", -fd)
                            }
                        } else {
                            kf.fmt_elem(&kf.add(&c0, &kf.mul(&kf.from_rational(a0), &c1)))
                        }
                    }
                    None => {
                        if f.is_zero(x) {
                            "0".into()
                        } else if let Some(c) = f.to_base(x) {
                            if imag {
                                "0".into()
                            } else {
                                f.base().fmt_elem(&c)
                            }
                        } else {
                            let p = if imag { "Im" } else { "Re" };
                            format!("{p}({})", f.fmt_elem(x))
                        }
                    }
                };
                (txt, val)
            };
            let one = f.one();
            for r in 0..n {
                for q in 0..m {
                    for (h, imag) in [(0, false), (1, true)] {
                        let (txt, val) = part(v.get(r, q), imag);
                        t[r][off + 2 * q + h] = txt;
                        ta[r][off + 2 * q + h] = val;
                    }
                }
            }
            let (ar, br) = (e.approx.0, e.approx.1);
            for r in 0..m {
                let (o, p) = (off + 2 * r, off + 2 * r + 1);
                j[o][o] = a_txt.clone();
                j[p][p] = a_txt.clone();
                j[o][p] = b_txt.clone();
                j[p][o] = format!("-{b_txt}");
                ja[o][o] = ar;
                ja[p][p] = ar;
                ja[o][p] = br;
                ja[p][o] = -br;
                if r + 1 < m && *jj.get(r, r + 1) == one {
                    j[o][o + 2] = "1".into();
                    j[p][p + 2] = "1".into();
                    ja[o][o + 2] = 1.0;
                    ja[p][p + 2] = 1.0;
                }
            }
            off += 2 * m;
        }
        let verified = self.verified && off == n;
        Ok(RealFormK {
            n,
            j,
            t,
            j_approx: ja,
            t_approx: ta,
            symbols,
            compact,
            verified,
        })
    }
}
