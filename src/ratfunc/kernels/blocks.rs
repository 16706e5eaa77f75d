//! Block splitting for the RREF and rank kernels of $\mathbb{Q}(p)$: the rows and columns of
//! an `m x n` matrix $A$ fall into the connected components of the bipartite graph whose edges
//! are the nonzero entries. Up to a permutation $A$ is block diagonal over the components, so
//!
//! - $\operatorname{rank} A = \sum_c \operatorname{rank} A_c$;
//! - the nonzero rows of the RREF of $A$ are the nonzero rows of the RREF of every $A_c$
//!   (written back into $A$'s columns), sorted by pivot column: such a row has its leading 1
//!   at its pivot column and zeros at every other pivot column (those of its own block by the
//!   block's RREF, those of other blocks because it vanishes outside its block's columns), and
//!   together they span the row space of $A$, the direct sum of the blocks' row spaces.
//!
//! Each block records its own conditions (the RREF of $A$ has its form exactly where every
//! block's has). A diagonal $A - \lambda I$ (the Jordan chains of diag(p0..p9)) splits into
//! `1 x 1` blocks instead of one interpolation in ten variables.

use crate::ratfunc::{RatFunc, RatFuncField};

/// One component: its rows and columns, increasing.
pub struct Block {
    pub rows: Vec<usize>,
    pub cols: Vec<usize>,
}

/// The components with at least one nonzero entry (zero rows and columns belong to none);
/// `None` when there are fewer than two (nothing to split).
pub fn split(k: &RatFuncField, m: usize, n: usize, a: &[RatFunc]) -> Option<Vec<Block>> {
    use crate::field::Field;
    // union-find over rows 0..m and columns m..m+n
    let mut parent: Vec<usize> = (0..m + n).collect();
    fn find(p: &mut [usize], mut x: usize) -> usize {
        while p[x] != x {
            p[x] = p[p[x]];
            x = p[x];
        }
        x
    }
    let mut touched = vec![false; m + n];
    for i in 0..m {
        for j in 0..n {
            if !k.is_zero(&a[i * n + j]) {
                touched[i] = true;
                touched[m + j] = true;
                let (x, y) = (find(&mut parent, i), find(&mut parent, m + j));
                if x != y {
                    parent[x] = y;
                }
            }
        }
    }
    let mut index = vec![usize::MAX; m + n];
    let mut blocks: Vec<Block> = Vec::new();
    for v in 0..m + n {
        if !touched[v] {
            continue;
        }
        let root = find(&mut parent, v);
        if index[root] == usize::MAX {
            index[root] = blocks.len();
            blocks.push(Block {
                rows: vec![],
                cols: vec![],
            });
        }
        let b = &mut blocks[index[root]];
        if v < m {
            b.rows.push(v);
        } else {
            b.cols.push(v - m);
        }
    }
    (blocks.len() >= 2).then_some(blocks)
}

/// The submatrix of `a` (`n` columns) on a block's rows and columns, row-major.
pub fn sub(a: &[RatFunc], n: usize, b: &Block) -> Vec<RatFunc> {
    b.rows
        .iter()
        .flat_map(|&i| b.cols.iter().map(move |&j| a[i * n + j].clone()))
        .collect()
}

/// The RREF of `a` (`m x n`) assembled from the RREFs of its blocks (`rref_of(block
/// matrix, rows, cols)`; `None` from any block gives `None`).
pub fn assemble(
    k: &RatFuncField,
    m: usize,
    n: usize,
    a: &[RatFunc],
    blocks: &[Block],
    mut rref_of: impl FnMut(&[RatFunc], usize, usize) -> Option<(Vec<RatFunc>, Vec<usize>)>,
) -> Option<(Vec<RatFunc>, Vec<usize>)> {
    use crate::field::Field;
    // (pivot column of A, row of A's RREF)
    let mut rows: Vec<(usize, Vec<RatFunc>)> = Vec::new();
    for b in blocks {
        let (bm, bn) = (b.rows.len(), b.cols.len());
        let (r, piv) = rref_of(&sub(a, n, b), bm, bn)?;
        for (row, &p) in piv.iter().enumerate() {
            let mut full = vec![k.zero(); n];
            for (jj, &j) in b.cols.iter().enumerate() {
                full[j] = r[row * bn + jj].clone();
            }
            rows.push((b.cols[p], full));
        }
    }
    rows.sort_by_key(|(p, _)| *p);
    let mut out = vec![k.zero(); m * n];
    let mut piv = Vec::with_capacity(rows.len());
    for (i, (p, row)) in rows.into_iter().enumerate() {
        out[i * n..(i + 1) * n].clone_from_slice(&row);
        piv.push(p);
    }
    Some((out, piv))
}
