//! Exact matrix kernels over $\mathbb{Q}$ on row-major `BigRational` slices.
//!
//! A leaf module: it depends only on `num-*` and [`crate::field::Rational`] (and
//! [`crate::field::Quadratic`] for the $\mathbb{Q}(\sqrt d)$ kernels of
//! [`modular::quadratic`]). The matrix layer ([`crate::matrix`]) calls these kernels when
//! the field is $\mathbb{Q}$ or $\mathbb{Q}(\sqrt d)$ and chooses between them by size (the
//! thresholds live in `crate::matrix::over_q` and `crate::matrix::over_k`).
//!
//! | module | contents |
//! |---|---|
//! | [`fraction_free`] | Bareiss determinant / RREF / rank / inverse, Berkowitz characteristic polynomial |
//! | [`modular`] | certified multi-modular RREF / rank / null space / determinant / characteristic polynomial / inverse (and determinant / characteristic polynomial over $\mathbb{Q}(\sqrt d)$) |
//! | [`intmul`] | the integer product kernel $C = AB$ (one gcd per entry) |
//! | [`intmat`] | integer matrices scaled from rational input |
//! | [`prime`] | word-size primes and arithmetic modulo them |
//! | [`gcd`] | Lehmer gcd on big integers, canonical fractions |

pub mod fraction_free;
pub(crate) mod gcd;
pub mod intmat;
pub(crate) mod intmul;
pub mod modular;
pub mod prime;
