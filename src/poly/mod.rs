//! Polynomials: dense integer polynomials ([`zpoly`]) and factorization over Q ([`factor`]).
pub mod factor;
pub mod zpoly;
