//! The Jordan-form method's results as data: the modal form over a field with certified
//! eigenvalues ([`JordanMinimal`], computed by [`super::minimal_jordan`]), the primary blocks
//! over the base field ([`PrimaryJordanMinimal`], by [`super::minimal_jordan_primary`] and
//! [`super::minimal_jordan_qp`]) and the choice between them ([`JordanMethod`], held by
//! [`super::MinimalRealization::jordan`]).
//!
//! Types only (and their accessors): the files that compute these results and the minimal
//! realization result that holds them import this file, never the other way round, so the
//! result type of every method ([`super::minimal`]) does not depend on the algorithms.

use crate::algebraic::{Ext, NumberField};
use crate::field::{Field, Q};
use crate::jordan::JordanForm;
use crate::jordan::pair_field::PairField;
use crate::jordan::primary::Component;
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// The Jordan-form method's result over a field, as the field decomposes $A$.
#[derive(Clone, Debug)]
pub enum JordanMethod<K: Field> {
    /// Over a field with certified eigenvalues: one block per eigenvalue (and the real form).
    Modal(Box<JordanMinimal<K>>),
    /// Over $\mathbb{Q}(p)$: eigenvalues in the field as Jordan blocks, the roots of an
    /// irreducible factor of degree $\ge 2$ as one primary block.
    Primary(Box<PrimaryJordanMinimal<K>>),
}

impl<K: Field> JordanMethod<K> {
    /// The method's own exact checks held.
    pub fn verified(&self) -> bool {
        match self {
            JordanMethod::Modal(m) => m.verified,
            JordanMethod::Primary(p) => p.verified,
        }
    }
}

/// One eigenvalue's block of the complex modal form, exact in $E$ at that eigenvalue.
#[derive(Clone, Debug)]
pub struct ModalBlock<F: Field = Q> {
    /// Index into the Jordan form's eigenvalues ([`JordanMinimal::jordan`]).
    pub eigenvalue: usize,
    /// $E = F(\theta)$ marked at the eigenvalue ([`crate::jordan::EigenField::root_field`]).
    pub field: Ext<F>,
    pub a: Matrix<Ext<F>>,
    pub b: Matrix<Ext<F>>,
    pub c: Matrix<Ext<F>>,
}

/// One block of the real modal form.
#[derive(Clone, Debug)]
pub enum RealModalBlock<F: Field = Q> {
    /// A real eigenvalue: its modal block, real entries exact in its field.
    Root(ModalBlock<F>),
    /// A complex pair $a \pm bi$ in its real field ([`PairField`]): blocks $[[a, b], [-b, a]]$
    /// with $I_2$ coupling, $x = [\mathrm{Re}\, z; -\mathrm{Im}\, z]$ interleaved,
    /// $B_r = [\mathrm{Re}\, WB; -\mathrm{Im}\, WB]$, $C_r = [2\,\mathrm{Re}\, CV,
    /// 2\,\mathrm{Im}\, CV]$.
    Pair {
        eigenvalue: usize,
        pair: PairField,
        a: Matrix<NumberField>,
        b: Matrix<NumberField>,
        c: Matrix<NumberField>,
    },
    /// A pair $a_0 \pm s\sqrt f$ of a rational quadratic factor over a quadratic field: the
    /// complex data of the upper root, whose entries $u + w\sqrt f$ have the exact real and
    /// imaginary parts $u$ and $w\sqrt{-f}$.
    Radical(ModalBlock<F>),
    /// A complex pair whose real field is large: the complex modal data of the upper root,
    /// the real block read off as the real and imaginary parts of its entries (compact form).
    Compact(ModalBlock<F>),
}

impl<F: Field> RealModalBlock<F> {
    /// Order of the real block.
    pub fn order(&self) -> usize {
        match self {
            RealModalBlock::Root(b) => b.a.nrows(),
            RealModalBlock::Pair { a, .. } => a.nrows(),
            RealModalBlock::Compact(b) | RealModalBlock::Radical(b) => 2 * b.a.nrows(),
        }
    }
    /// Index of the eigenvalue (the upper root of a pair).
    pub fn eigenvalue(&self) -> usize {
        match self {
            RealModalBlock::Pair { eigenvalue, .. } => *eigenvalue,
            RealModalBlock::Root(b) | RealModalBlock::Compact(b) | RealModalBlock::Radical(b) => {
                b.eigenvalue
            }
        }
    }
    /// Whether the block is a complex pair.
    pub fn is_pair(&self) -> bool {
        !matches!(self, RealModalBlock::Root(_))
    }
}

impl RealModalBlock<Q> {
    /// The block's field and $(A, B, C)$ when it is written in one real number field (a
    /// real root, or an expanded pair).
    pub fn exact_entries(&self) -> Option<(&NumberField, [&Matrix<NumberField>; 3])> {
        match self {
            RealModalBlock::Root(b) => Some((&b.field, [&b.a, &b.b, &b.c])),
            RealModalBlock::Pair { pair, a, b, c, .. } => Some((&pair.field, [a, b, c])),
            _ => None,
        }
    }
}

/// The Jordan-method minimal realization.
#[derive(Clone, Debug)]
pub struct JordanMinimal<F: Field = Q> {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    /// The Jordan form of $A$ (the eigenvalues the blocks refer to).
    pub jordan: JordanForm<F>,
    /// The complex modal form: one block per retained eigenvalue.
    pub blocks: Vec<ModalBlock<F>>,
    /// Over a real field: the real modal form (per retained eigenvalue or pair).
    pub real: Option<Vec<RealModalBlock<F>>>,
    pub d: Matrix<F>,
    pub mcmillan_degree: usize,
    pub verified: bool,
}

impl<F: Field> JordanMinimal<F> {
    /// Order of the realization.
    pub fn order(&self) -> usize {
        self.stages[2]
    }
}

/// One retained component in the realization over $F$.
#[derive(Clone, Debug, PartialEq)]
pub struct PrimaryBlock<F: Field> {
    /// Index into [`PrimaryJordanMinimal::components`].
    pub component: usize,
    /// Jordan block sizes of each root after the compaction, largest first.
    pub blocks: Vec<usize>,
    /// First state of the block in [`PrimaryJordanMinimal::system`] and its number of states
    /// (sum of `blocks` times the degree of the factor).
    pub offset: usize,
    pub order: usize,
    /// $(J, B, C)$ over $E$ (marked as the component's field) before the regular
    /// representation ($0 \times 0$ for a simple factor's restriction block).
    pub modal: [Matrix<Ext<F>>; 3],
}

impl<F: Field> PrimaryBlock<F> {
    /// The block is a simple factor's restriction $(A_g, P B, C u)$ (module docs), not a
    /// regular representation.
    pub fn is_restriction(&self) -> bool {
        self.modal[0].nrows() == 0
    }
}

/// The Jordan-method minimal realization over $F$ (module docs).
#[derive(Clone, Debug)]
pub struct PrimaryJordanMinimal<F: Field> {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    /// One component per irreducible factor of $\chi_A$ over $F$.
    pub components: Vec<Component<F>>,
    /// The retained components, in the order of their states.
    pub blocks: Vec<PrimaryBlock<F>>,
    /// The minimal realization $(A_F, B_F, C_F, D)$.
    pub system: StateSpace<F>,
    pub mcmillan_degree: usize,
    /// The checks of the module docs held exactly.
    pub verified: bool,
}
