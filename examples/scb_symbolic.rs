//! Grip & Saberi's SCB examples in symbols (issue 13): the linear single-track model
//! (sec. IV, front steering, then rear steering added) and the DC motor with LuGre friction
//! (sec. V, eq. 8), each over $\mathbb{Q}(p)$, with the conditions the derivation assumes, the
//! paper's printed matrices checked (two errata), and the structural bifurcations of the DC
//! motor found by the program (σ₁ = 0: one integrator chain of length three).
//!
//! Run: `cargo run --example scb_symbolic`

use exactlti::field::ElemDisplay;
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::report::sections::{branch_equation, branch_reason};
use exactlti::structure::bifurcation::{BranchOutcome, Limits, Node, bifurcations};
use exactlti::structure::scb::{Scb, scb};
use exactlti::system::StateSpace;
use std::path::Path;

fn load(path: &str) -> StateSpace<RatFuncField> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let l = load_symbolic_path(&root.join(path), &SymbolicOptions::default()).expect(path);
    let TypedAny::RatFunc(t) = l.system else {
        panic!("{path}: expected symbolic parameters")
    };
    t.ss
}

fn show(name: &str, m: &Matrix<RatFuncField>) {
    let k = m.field();
    println!("  {name} =");
    for i in 0..m.nrows() {
        let row: Vec<String> = (0..m.ncols()).map(|j| k.fmt_elem(m.get(i, j))).collect();
        println!("    [{}]", row.join(",  "));
    }
}

/// The SCB on a fresh condition log, with its conditions.
fn derive(s: &StateSpace<RatFuncField>) -> exactlti::Result<(Scb<RatFuncField>, Vec<String>)> {
    let k = s.a.field().fresh();
    let m = |x: &Matrix<RatFuncField>| x.map(&k, |e| e.clone());
    let r = scb(&m(&s.a), &m(&s.b), &m(&s.c), &m(&s.d))?;
    Ok((r, k.conditions_strings()?))
}

fn report(r: &Scb<RatFuncField>, conds: &[String]) {
    println!(
        "  dims (n_a, n_b, n_c, n_d) = {:?}, chains {:?}",
        r.dims, r.chains
    );
    println!(
        "  left invertible {}, right invertible {}; zero polynomial {}",
        r.left_invertible,
        r.right_invertible,
        r.invariant_zero_polynomial().to_string_var("s")
    );
    show("A (SCB)", &r.a);
    show("B (SCB)", &r.b);
    show("C (SCB)", &r.c);
    println!("  assumes nonzero: {}", conds.join(", "));
    println!(
        "  verified (sec. II-C identities as rational functions): {}",
        r.verified
    );
}

fn paper_matrix(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
    let data = rows
        .iter()
        .flat_map(|r| r.iter().map(|x| k.parse(x).expect("paper entry")))
        .collect();
    Matrix::from_vec(k.clone(), rows.len(), rows[0].len(), data)
}

fn tree(k: &RatFuncField, n: &Node<[usize; 4]>, indent: usize) {
    let pad = " ".repeat(indent);
    for b in &n.branches {
        match &b.outcome {
            BranchOutcome::Explored(c) => {
                println!(
                    "{pad}{} = 0  ({}): dims {:?}{}",
                    k.fmt_poly(&b.condition),
                    branch_equation(k, b),
                    c.result,
                    if c.result != n.result {
                        "  <- structure changes"
                    } else {
                        ""
                    }
                );
                tree(k, c, indent + 2);
            }
            BranchOutcome::Undefined | BranchOutcome::NotExplored(_) => {
                let why = branch_reason(k, b).unwrap_or_default();
                println!("{pad}{} = 0: {why}", k.fmt_poly(&b.condition));
            }
        }
    }
}

fn main() -> exactlti::Result<()> {
    println!("== Sec. IV: linear single-track model, front steering (A-hat, B-hat, C-hat)");
    let front = load("data/scb/single-track-front.json");
    show("A-hat", &front.a);
    let (r, conds) = derive(&front)?;
    report(&r, &conds);
    println!(
        "  paper: dim = 0, 3, 0, 1 (x_b observable chain, x_d one integrator); ours: {:?}",
        r.dims
    );

    println!("\n== Sec. IV: rear-axle steering added (B-hat gets [0, 0, 0, c_r/T_r]^T)");
    let rear = load("data/scb/single-track-rear.json");
    let (r, conds) = derive(&rear)?;
    report(&r, &conds);
    let k = rear.a.field();
    let printed = paper_matrix(
        k,
        &[
            &["0", "1", "-vx", "0"],
            &[
                "-(cf + cr)/(m*Tr*vx)",
                "-1/Tr",
                "(lr*cr - lf*cf)/(m*Tr*vx)",
                "0",
            ],
            &["0", "0", "0", "1"],
            &[
                "(lr*cr - lf*cf)/(J*Tr*vx)",
                "0",
                "(lf^2*cf + lr^2*cr)/(J*Tr*vx)",
                "-1/Tr",
            ],
        ],
    );
    println!(
        "  paper's A as printed similar to A-hat (same charpoly)? {}",
        printed.charpoly()? == rear.a.charpoly()?
    );
    println!(
        "  erratum: entry (4, 3) must be {} (ours), the paper prints {}",
        k.fmt_elem(r.a.get(3, 2)),
        k.fmt_elem(printed.get(3, 2))
    );
    println!(
        "  A_aa = {}: a zero at the origin (non-minimum phase)",
        k.fmt_elem(r.a.get(0, 0))
    );

    println!("\n== Sec. V: DC motor with LuGre friction, eq. (8)");
    let dc = load("data/dc-motor-lugre.json");
    show("A-hat (8)", &dc.a);
    show("B-hat (8)", &dc.b);
    let (r, conds) = derive(&dc)?;
    report(&r, &conds);
    let k = dc.a.field();
    println!(
        "  A_12: ours {}, the paper prints -sigma0*(sigma0*J - sigma1*alpha2)/sigma1^2 (erratum: sigma1^3, as its own numbers -592.7 confirm)",
        k.fmt_elem(r.a.get(0, 1))
    );

    println!("\n== Sec. VI outlook: structural bifurcations of the DC motor's SCB (depth 2)");
    let f = |s: &StateSpace<RatFuncField>| scb(&s.a, &s.b, &s.c, &s.d).map(|r| r.dims);
    let t = bifurcations(&dc, &f, Limits::default())?;
    println!("generic: dims {:?}", t.result);
    tree(k, &t, 2);
    Ok(())
}
