//! LaTeX made from values (field elements, polynomials, algebraic numbers), never re-parsed
//! from their display text: each coefficient through its field's `latex_elem`, each
//! monomial `c\,x^{k}` with the sign of the coefficient pulled into the sum.

use crate::algebraic::{AlgebraicNumber, Ext};
use crate::field::ElemDisplay;
use crate::field::{Field, Q};
use crate::poly::Poly;
use crate::report::display::quadratic_latex;
use crate::report::display::{LATEX, closed_form_latex, poly_sum};

/// The polynomial with coefficients `cs` (low degree first) in `var`, each coefficient
/// typeset by `elem` (compound ones in parentheses): `x^{2} - \frac{1}{2} x + 3` (the one
/// sum writer of the text display, [`crate::report::display::poly_sum`], in its LaTeX style).
pub fn poly_latex<K: Field>(
    k: &K,
    cs: &[K::Elem],
    var: &str,
    elem: &dyn Fn(&K::Elem) -> String,
) -> String {
    poly_sum(k, cs, var, elem, &LATEX)
}

/// An element of $F[t]/(g)$: the field's closed form when it has one ($a + b\sqrt d$),
/// else the polynomial in its generator with the base field's LaTeX coefficients.
pub fn ext_latex<F: Field>(e: &Ext<F>, a: &<Ext<F> as Field>::Elem) -> String {
    let closed = e.latex_elem(a);
    if closed != e.fmt_elem(a) {
        return closed;
    }
    let base = e.base();
    poly_latex(base, e.coeffs(a), e.var(), &|c| base.latex_elem(c))
}

/// A polynomial over $F[t]/(g)$ in `var`, its coefficients by [`ext_latex`].
pub fn poly_over_ext_latex<F: Field>(p: &Poly<Ext<F>>, var: &str) -> String {
    let e = p.field();
    poly_latex(e, p.coeffs(), var, &|c| ext_latex(e, c))
}

/// An algebraic number from its value: $a + b\sqrt d$ from its quadratic parts, the nested
/// radicals of a biquadratic from theirs ([`closed_form_latex`]), `root of` its minimal
/// polynomial `near` its certified digits otherwise.
pub fn algebraic_latex(a: &AlgebraicNumber) -> String {
    if let Some((x, y, d)) = a.quadratic_parts() {
        return quadratic_latex(&x, &y, &d);
    }
    if a.degree() == 4
        && let Some(l) = closed_form_latex(a.minpoly(), a.approx())
    {
        return l;
    }
    let (re, im) = a.digits(10);
    let near =
        crate::report::display::near_text(&re, &im, a.is_real()).replace("*i", "\\,\\mathrm{i}");
    format!(
        "\\text{{root of }} {} \\text{{ near }} {near}",
        poly_latex(&Q, a.minpoly().coeffs(), "x", &|c| Q.latex_elem(c))
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::ElemDisplay;
    use crate::field::Rational;

    fn q(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn polynomials_and_numbers_from_their_values() {
        let p = [q(3, 1), q(-1, 2), q(1, 1)];
        assert_eq!(
            poly_latex(&Q, &p, "x", &|c| Q.latex_elem(c)),
            "x^{2} - \\frac{1}{2} x + 3"
        );
        // over Q(t), t^2 - 3 t + 1 (not a pure radical): coefficients are polynomials in t
        let f = Poly::new(Q, vec![q(1, 1), q(-3, 1), q(1, 1)]);
        let e = Ext::with_var(&f, (2.618, 0.0), "t");
        let c = e.from_poly(&Poly::new(Q, vec![q(1, 3), q(-303, 976)]));
        let lin = Poly::new(e.clone(), vec![c, e.one()]);
        assert_eq!(
            poly_over_ext_latex(&lin, "x"),
            "x + \\left(-\\frac{303}{976} t + \\frac{1}{3}\\right)"
        );
        let two = Poly::new(Q, vec![q(-2, 1), q(0, 1), q(1, 1)]);
        let r = AlgebraicNumber::roots_of_irreducible(&two).unwrap();
        assert_eq!(algebraic_latex(&r[0]), "-\\sqrt{2}");
        let cubic = Poly::new(Q, vec![q(-2, 1), q(0, 1), q(0, 1), q(1, 1)]);
        let c = AlgebraicNumber::roots_of_irreducible(&cubic)
            .unwrap()
            .remove(0);
        assert_eq!(
            algebraic_latex(&c),
            "\\text{root of } x^{3} - 2 \\text{ near } 1.259921050"
        );
    }
}

#[cfg(test)]
mod matrix_tests {
    use crate::field::{ElemDisplay, Field, QuadraticField, Rational};
    use crate::matrix::Matrix;
    use crate::ratfunc::RatFuncField;
    use crate::report::{MatrixOut, Target};

    #[test]
    fn latex_matrices_are_typeset_from_their_elements() {
        // Q(cr, m, u): the field's LaTeX (\mathit names), not the text re-parsed
        let k = RatFuncField::new(&["cr", "m", "u"]).unwrap();
        let x = k.parse("-cr/(m*u)").unwrap();
        let m = Matrix::from_vec(k.clone(), 1, 2, vec![x.clone(), k.one()]);
        let out = MatrixOut::for_target(&m, Target::Latex);
        assert_eq!(out.latex_at(0, 0), Some(k.latex_elem(&x).as_str()));
        assert!(out.latex_at(0, 0).unwrap().contains("\\mathit{cr}"));
        assert_eq!(out.latex_at(0, 1), None, "1: the same as its text");
        // Q(sqrt 2): a + b sqrt(2) from its parts
        let q2 = QuadraticField::new(2).unwrap();
        let half = Rational::new(1.into(), 2.into());
        let y = crate::field::Quadratic::new(half.clone(), -half);
        let m2 = Matrix::from_vec(q2.clone(), 1, 1, vec![y]);
        let out2 = MatrixOut::for_target(&m2, Target::Latex);
        assert_eq!(
            out2.latex_at(0, 0),
            Some("\\frac{1}{2} - \\frac{\\sqrt{2}}{2}")
        );
        // other targets build no LaTeX
        assert!(
            MatrixOut::for_target(&m2, Target::Json)
                .latex_at(0, 0)
                .is_none()
        );
    }
}
