//! Report of the Jordan-method minimal realization written over the base field
//! ([`PrimaryJordanMinimal`], over $\mathbb{Q}(p)$ for `minreal --method jordan`).
//!
//! Presentation only: strings are made here from the result's values.

use crate::field::Field;
use crate::realization::PrimaryJordanMinimal;
use crate::report::{Report, Value, str_list};

impl<F: Field> PrimaryJordanMinimal<F> {
    /// One line per retained component: its eigenvalue (a factor of degree 1) or the factor
    /// whose roots its primary block carries, with the Jordan block sizes and its states.
    pub fn mode_lines(&self) -> Vec<String> {
        let k = self.system.a.field();
        self.blocks
            .iter()
            .map(|b| {
                let comp = &self.components[b.component];
                let g = &comp.factor;
                let sizes: Vec<String> = b.blocks.iter().map(|s| s.to_string()).collect();
                let states = format!("states {}..{}", b.offset + 1, b.offset + b.order);
                if g.deg() == 1 {
                    let theta = k.neg(&g.monic().coeff(0));
                    format!(
                        "eigenvalue {} (Jordan blocks {}): {states}",
                        k.fmt_elem(&theta),
                        sizes.join(", ")
                    )
                } else {
                    format!(
                        "roots of {} (Jordan blocks {} per root; primary block, regular \
                         representation of the factor's field in the basis 1, t, .., t^{}): \
                         {states}",
                        g.to_string_var("s"),
                        sizes.join(", "),
                        g.deg() - 1
                    )
                }
            })
            .collect()
    }
    /// The CLI report: `method`, `field`, `original_order`, `order`, `mcmillan_degree`,
    /// `stages`, `A`..`D`, `modes`, `presentation`, `verified`.
    pub fn report(&self) -> Report {
        let s = &self.system;
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .str("field", s.a.field().to_string())
            .int("original_order", self.stages[0])
            .int("order", s.nstates())
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&x| Value::Int(x as i64)).collect()),
            )
            .matrix("A", &s.a)
            .matrix("B", &s.b)
            .matrix("C", &s.c)
            .matrix("D", &s.d)
            .with("modes", str_list(self.mode_lines()))
            .str(
                "presentation",
                "modal form over the base field: an eigenvalue in the field as its Jordan \
                 blocks, the roots of an irreducible factor of degree d >= 2 as one primary \
                 block (d states per Jordan state); verified by C A^k B equal for k < n + r and \
                 the order equal to the McMillan degree",
            )
            .bool("verified", self.verified)
    }
}

/// A matrix over any field as rows of exact strings.
fn rows<K: Field>(m: &crate::matrix::Matrix<K>) -> Value {
    let k = m.field();
    Value::List(
        (0..m.nrows())
            .map(|i| str_list(m.row(i).iter().map(|x| k.fmt_elem(x))))
            .collect(),
    )
}

impl crate::jordan::over_qp::QpRealForm {
    /// The CLI report of `jordan --real` over $\mathbb{Q}(p)$: `field`, `n`, `charpoly`,
    /// `components[]` (an eigenvalue in $\mathbb{Q}(p)$ with `blocks` and its chains `T`, or
    /// a pair with `factor`, `real_part`, `imaginary_part`, `complex_where`, `blocks`,
    /// `J_real`, `T_real` over $\mathbb{Q}(p)(w)$), `conditions`, `verified`.
    pub fn report(&self) -> Report {
        let k = self.a.field();
        let comps = self
            .components
            .iter()
            .zip(&self.pairs)
            .map(|(c, pair)| {
                let blocks = Value::List(c.blocks.iter().map(|&b| Value::Int(b as i64)).collect());
                let r = match pair {
                    None => {
                        let theta = k.neg(&c.factor.monic().coeff(0));
                        let e = &c.field;
                        let t = c
                            .chains
                            .map(k, |x| e.to_base(x).unwrap_or_else(|| k.zero()));
                        Report::new()
                            .str("eigenvalue", k.fmt_elem(&theta))
                            .with("blocks", blocks)
                            .with("T", rows(&t))
                    }
                    Some(p) => {
                        let w = p.field.var();
                        Report::new()
                            .str("factor", c.factor.to_string_var("s"))
                            .str("real_part", k.fmt_elem(&p.re))
                            .str(
                                "imaginary_part",
                                format!("{w} = sqrt({})", k.fmt_elem(&p.im_squared)),
                            )
                            .str(
                                "complex_where",
                                format!("{} < 0", k.fmt_elem(&p.discriminant)),
                            )
                            .with("blocks", blocks)
                            .with("J_real", rows(&p.j))
                            .with("T_real", rows(&p.t))
                            .bool("verified", p.verified)
                    }
                };
                Value::Obj(r)
            })
            .collect();
        Report::titled("real Jordan form over QQ(p)")
            .str("field", k.to_string())
            .int("n", self.a.nrows())
            .str("charpoly", self.charpoly.charpoly.to_string_var("s"))
            .list("components", comps)
            .str(
                "presentation",
                "eigenvalues in QQ(p) with their Jordan chains; each quadratic factor s^2 + b s + c \
                 as blocks [[a, w], [-w, a]] (I2 coupling), a = -b/2, w = sqrt(c - b^2/4), a \
                 complex pair exactly where b^2 - 4c < 0; A T = T J checked exactly with w a \
                 symbol (w^2 = c - b^2/4)",
            )
            .bool("verified", self.verified)
    }
}
