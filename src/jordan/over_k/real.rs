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
//! Presentation, as over $\mathbb{Q}$: a pair whose real field $F = K(\operatorname{Re}
//! \theta, \operatorname{Im}\theta)$ has degree at most
//! [`crate::jordan::real::EXPAND_MAX_DEGREE`] (always with `expand`, up to
//! [`super::pair_field::EXPAND_MAX_PRIMITIVE_DEGREE`]) is written in $F$
//! ([`super::pair_field`]) and checked there: $A T = T J$ exactly. Otherwise (the compact
//! form of the rational real Jordan form) a pair's entries are
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
    /// The real fields of degree $\ge 3$ of expanded pairs (`c<k> = ...`) and their
    /// eigenvalues' parts in them (`r<k> = a + (b)*i`).
    pub fields: Vec<String>,
    /// Pairs that `--expand` could not expand, one line each.
    pub notes: Vec<String>,
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
        self.real_form_with(false)
    }
    /// The real Jordan form; `expand` writes every complex pair in its real field
    /// $F = K(\operatorname{Re}\theta, \operatorname{Im}\theta)$ whatever its degree
    /// (by default only when it has degree at most
    /// [`crate::jordan::real::EXPAND_MAX_DEGREE`], as over $\mathbb{Q}$); a pair whose field
    /// cannot be built stays compact, with a note.
    ///
    /// # Errors
    /// As [`JordanFormK::real_form`].
    pub fn real_form_with(&self, expand: bool) -> Result<RealFormK> {
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
        let (mut fields, mut notes) = (vec![], vec![]);
        let mut verified = self.verified;
        let mut off = 0;
        for (ev, (f, v, jj)) in self.root_columns().into_iter().enumerate() {
            let e = &self.eigenvalues[ev];
            let m = v.ncols();
            if e.approx.1 == 0.0 || e.number.is_real() {
                // a real root written through its symbol r<k> is defined with the fields
                if f.0.radical.is_none() && self.components[e.component].factor.deg() >= 2 {
                    fields.push(self.root_definition(ev));
                }
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
            if radical.is_none() {
                let g = &self.components[e.component].factor;
                let var = format!("c{}", &e.symbol[1..]);
                match super::pair_field::pair_field(g, e.approx, &var, expand) {
                    Ok(Some(pf)) => {
                        let cells = Cells {
                            j: &mut j,
                            t: &mut t,
                            ja: &mut ja,
                            ta: &mut ta,
                        };
                        let (ok, lines) = expanded_pair(&self.a, &pf, (&v, &jj), e, off, cells);
                        verified &= ok;
                        fields.extend(pf.symbol());
                        fields.extend(lines);
                        off += 2 * m;
                        continue;
                    }
                    Ok(None) => {}
                    Err(err) if expand => notes.push(format!(
                        "eigenvalue {}: exact real field not found ({err}); compact exact form \
                         given instead",
                        e.value
                    )),
                    Err(_) => {}
                }
            }
            let (a_txt, b_txt) = match &radical {
                Some((a0, s, fd)) => (crate::field::fmt_rational(a0), im_radical(s, &-fd)),
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
                    Some(_) => radical_part(&f, x, imag).unwrap_or_default(),
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
        let verified = verified && off == n;
        Ok(RealFormK {
            n,
            j,
            t,
            j_approx: ja,
            t_approx: ta,
            symbols,
            fields,
            notes,
            compact,
            verified,
        })
    }
}

impl JordanFormK {
    /// `r<k> = root of P near X (over K: root of g)`: the definition of the symbol of
    /// eigenvalue `ev` (its minimal polynomial over $\mathbb{Q}$, an isolating
    /// approximation, and its factor over $K$), as in the `symbols` of the complex report.
    pub fn root_definition(&self, ev: usize) -> String {
        let e = &self.eigenvalues[ev];
        format!(
            "{} = {} (over {}: root of {})",
            e.symbol,
            e.value,
            self.base(),
            self.components[e.component].factor
        )
    }
}

/// The matrices of the real form under construction.
struct Cells<'a> {
    j: &'a mut [Vec<String>],
    t: &'a mut [Vec<String>],
    ja: &'a mut [Vec<f64>],
    ta: &'a mut [Vec<f64>],
}

/// Writes the pair of eigenvalue `e` (chains `v`, block `jj` in $E$ at $\theta$) expanded
/// into its real field at column `off`, and checks $A T = T J$ exactly in $F$; returns the
/// check and, for a field of degree $\ge 3$, the line `r<k> = a + (b)*i`.
fn expanded_pair(
    a: &crate::matrix::Matrix<crate::field::QuadraticField>,
    pf: &super::pair_field::PairField,
    (v, jj): (
        &crate::matrix::Matrix<super::RelField>,
        &crate::matrix::Matrix<super::RelField>,
    ),
    e: &crate::jordan::Eigenvalue,
    off: usize,
    c: Cells<'_>,
) -> (bool, Vec<String>) {
    use crate::matrix::Matrix;
    let f = &pf.field;
    let (n, m) = (v.nrows(), v.ncols());
    let mut tm = Matrix::zeros(f.clone(), n, 2 * m);
    for r in 0..n {
        for q in 0..m {
            let (re, im) = pf.re_im(v.get(r, q));
            tm.set(r, 2 * q, re);
            tm.set(r, 2 * q + 1, im);
        }
    }
    let (ar, bi) = (&pf.theta.re, &pf.theta.im);
    let mut jm = Matrix::zeros(f.clone(), 2 * m, 2 * m);
    let one = jj.field().one();
    for r in 0..m {
        let (o, p) = (2 * r, 2 * r + 1);
        jm.set(o, o, ar.clone());
        jm.set(p, p, ar.clone());
        jm.set(o, p, bi.clone());
        jm.set(p, o, f.neg(bi));
        if r + 1 < m && *jj.get(r, r + 1) == one {
            jm.set(o, o + 2, f.one());
            jm.set(p, p + 2, f.one());
        }
    }
    for r in 0..n {
        for q in 0..2 * m {
            c.t[r][off + q] = f.fmt_elem(tm.get(r, q));
            c.ta[r][off + q] = f.approx(tm.get(r, q)).0;
        }
    }
    for r in 0..2 * m {
        for q in 0..2 * m {
            c.j[off + r][off + q] = f.fmt_elem(jm.get(r, q));
            c.ja[off + r][off + q] = f.approx(jm.get(r, q)).0;
        }
    }
    let ok = &pf.matrix(a) * &tm == &tm * &jm;
    let lines = if f.degree() >= 3 {
        vec![format!(
            "{} = {} + ({})*i",
            e.symbol,
            f.fmt_elem(ar),
            f.fmt_elem(bi)
        )]
    } else {
        vec![]
    };
    (ok, lines)
}

/// `Re x` (`imag` false) or `Im x` of $x \in E$ at a root $\theta = a_0 + s\sqrt f$
/// ($f < 0$) of a rational quadratic factor, exact: $x = c_0 + c_1\theta$ has
/// $\operatorname{Re} x = c_0 + a_0 c_1 \in K$ and $\operatorname{Im} x = (s c_1)
/// \sqrt{-f}$, written `u` and `w*sqrt(-f)` (`None` without the radical form).
pub(crate) fn radical_part(f: &super::RelField, x: &super::RelElem, imag: bool) -> Option<String> {
    let (a0, s, fd) = f.0.radical.as_ref()?;
    let kf = f.base();
    let c0 = x.0.first().cloned().unwrap_or_else(|| kf.zero());
    let c1 = x.0.get(1).cloned().unwrap_or_else(|| kf.zero());
    if !imag {
        return Some(kf.fmt_elem(&kf.add(&c0, &kf.mul(&kf.from_rational(a0), &c1))));
    }
    let w = kf.mul(&kf.from_rational(s), &c1);
    let g = -fd;
    let rad = format!("sqrt({g})");
    Some(match kf.to_rational(&w) {
        Some(q) => im_radical(&q, &g),
        None if num_traits::One::is_one(&g) => kf.fmt_elem(&w),
        None => {
            let wt = kf.fmt_elem(&w);
            if wt[1..].contains([' ', '+', '-']) {
                format!("({wt})*{rad}")
            } else {
                format!("{wt}*{rad}")
            }
        }
    })
}

/// $q\sqrt g$ for rational $q$ and square-free $g > 0$ (`q` itself when $g = 1$).
fn im_radical(q: &crate::field::Rational, g: &num_bigint::BigInt) -> String {
    if num_traits::One::is_one(g) {
        crate::field::fmt_rational(q)
    } else {
        crate::field::quadratic::fmt_pair(&num_traits::Zero::zero(), q, &format!("sqrt({g})"))
    }
}
