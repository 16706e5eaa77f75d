//! A condition of a result over $\mathbb{Q}(p)$: an irreducible polynomial $f$ in the
//! parameters with the **reason** the result needs $f \ne 0$, as data ([`Reason`]); the
//! sentences are made in `report` (`report::sections::conditions`).
//!
//! A result over $\mathbb{Q}(p)$ holds for every parameter value off the zero sets of its
//! conditions. Which polynomials a command lists (its *condition set*) is decided by the
//! command (`api::symbolic`): only polynomials where the result really changes or is
//! undefined ([`Reason::InputDenominator`], [`Reason::StructureChange`],
//! [`Reason::PoleOfEntry`]); a bare pivot of one elimination ([`Reason::Pivot`],
//! [`Reason::ProofMinor`]) is what the generic log records and is listed only by commands
//! whose result is that elimination's (the RREF of `linalg rref`).

use crate::mpoly::MPoly;

/// A matrix of the input or of the result, named by its role.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Part {
    /// The state matrix $A$ (of the input, or of the result).
    A,
    B,
    C,
    D,
    /// The descriptor matrix $E$.
    E,
    /// The transformation $T$ of a result.
    T,
    /// Its inverse.
    TInv,
    /// The SCB's state, output and input transformations and its pre-transformations.
    Gamma1,
    Gamma2,
    Gamma3,
    U,
    Y,
    /// The result matrix of a `linalg` command.
    Result,
}

/// The structure that changes where a condition vanishes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Structure {
    /// The rank of a matrix drops below `rank` (the polynomial divides every
    /// `rank x rank` minor).
    Rank { rank: usize },
    /// The dimension of the controllable subspace (rank of $[B, AB, \dots, A^{n-1} B]$)
    /// drops below `dim`.
    Controllable { dim: usize },
    /// The dimension of the observable subspace drops below `dim`.
    Observable { dim: usize },
    /// The rank of the Krylov block $[B, AB, \dots, A^{j-1} B]$ (`blocks` $= j$) drops below
    /// `rank`: the controllability (observability, `dual`) indices change.
    Krylov {
        blocks: usize,
        rank: usize,
        dual: bool,
    },
    /// The McMillan degree (the rank of the Hankel matrix of the Markov parameters) drops
    /// below `degree`.
    McMillanDegree { degree: usize },
    /// $\deg_s \det(sE - A)$ drops below `degree`: the pencil loses a finite eigenvalue.
    FiniteEigenvalues { degree: usize },
    /// $\det(sE - A) = 0$ for every $s$: the pencil becomes singular.
    SingularPencil,
    /// A coefficient of the monic zero polynomial (of degree `degree`) has a pole: a zero
    /// goes to infinity, the number of finite invariant zeros changes.
    ZeroEscapes { degree: usize },
    /// The leading coefficient of an irreducible factor of $\chi_A$ vanishes.
    FactorDegree,
    /// The discriminant of an irreducible factor of $\chi_A$ vanishes: two of its
    /// eigenvalues meet (the Jordan blocks may change).
    RepeatedEigenvalue,
    /// The resultant of two factors of $\chi_A$ vanishes: eigenvalues of different factors
    /// meet.
    EigenvaluesMeet,
    /// $\det T = 0$: the basis of the result is singular.
    SingularBasis,
}

/// Why a polynomial is a condition of a result.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Reason {
    /// A denominator of entry (`row`, `col`) of input matrix `part`: the model itself is
    /// undefined where it vanishes.
    InputDenominator { part: Part, row: usize, col: usize },
    /// The named structure changes where it vanishes.
    StructureChange(Structure),
    /// A denominator of entry (`row`, `col`) of result matrix `part`: the result as written
    /// is undefined where it vanishes.
    PoleOfEntry { part: Part, row: usize, col: usize },
    /// A nonzero `size x size` minor at a random point proved a rank or pivot pattern: the
    /// proof needs it nonzero (the rank may or may not drop where it vanishes).
    ProofMinor { size: usize },
    /// A divisor of the generic elimination (a pivot): the computation assumed it nonzero.
    Pivot,
}

impl Reason {
    /// Does the result really change or become undefined where the condition vanishes?
    /// (`false` for the bookkeeping reasons of one elimination.)
    pub fn is_meaningful(&self) -> bool {
        !matches!(self, Reason::Pivot | Reason::ProofMinor { .. })
    }
}

/// An irreducible polynomial (primitive, positive leading coefficient) that must not vanish,
/// with the first [`Reason`] found for it (the order of [`Reason`]: input, structure, pole,
/// proof, pivot).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Condition {
    pub poly: MPoly,
    pub reason: Reason,
}
