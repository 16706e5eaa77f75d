//! The one integration-test binary: every former `tests/*.rs` file is a module here (one
//! link step instead of thirteen). A new test file must be listed below; the test
//! `every_test_file_is_a_module` fails otherwise. Run one former file with
//! `cargo test --test all FILE::` (e.g. `cargo test --test all jordan::`).

mod common;
#[path = "common/jordan.rs"]
mod jcommon;

#[path = "algebraic.rs"]
mod algebraic;
#[path = "analyze_fields.rs"]
mod analyze_fields;
#[path = "api.rs"]
mod api;
#[path = "api_fields.rs"]
mod api_fields;
#[path = "api_fields_generic.rs"]
mod api_fields_generic;
#[path = "as_written.rs"]
mod as_written;
#[path = "balred.rs"]
mod balred;
#[path = "bicycle.rs"]
mod bicycle;
#[path = "cli.rs"]
mod cli;
#[path = "cli_hardening.rs"]
mod cli_hardening;
#[path = "cli_interconnect.rs"]
mod cli_interconnect;
#[path = "cli_mpoly.rs"]
mod cli_mpoly;
#[path = "cli_options.rs"]
mod cli_options;
#[path = "cli_pencil.rs"]
mod cli_pencil;
#[path = "conditions_reasons.rs"]
mod conditions_reasons;
#[path = "connect_file.rs"]
mod connect_file;
#[path = "critical_fields.rs"]
mod critical_fields;
#[path = "critical_values.rs"]
mod critical_values;
#[path = "ctrb_structure.rs"]
mod ctrb_structure;
#[path = "dcgain.rs"]
mod dcgain;
#[path = "descriptor_class.rs"]
mod descriptor_class;
#[path = "descriptor_qp_speed.rs"]
mod descriptor_qp_speed;
#[path = "discrete.rs"]
mod discrete;
#[path = "discrete_text.rs"]
mod discrete_text;
#[path = "display.rs"]
mod display;
#[path = "elem_values.rs"]
mod elem_values;
#[path = "everyday.rs"]
mod everyday;
#[path = "failure_class.rs"]
mod failure_class;
#[path = "field_axioms.rs"]
mod field_axioms;
#[path = "fields_float.rs"]
mod fields_float;
#[path = "float.rs"]
mod float;
#[path = "float_eigen.rs"]
mod float_eigen;
#[path = "float_era.rs"]
mod float_era;
#[path = "float_honesty.rs"]
mod float_honesty;
#[path = "from_transfer.rs"]
mod from_transfer;
#[path = "fuzz.rs"]
mod fuzz;
#[path = "g_in_z.rs"]
mod g_in_z;
#[path = "gram_stability_fields.rs"]
mod gram_stability_fields;
#[path = "inputs.rs"]
mod inputs;
#[path = "interconnect.rs"]
mod interconnect;
#[path = "io.rs"]
mod io;
#[path = "jordan.rs"]
mod jordan;
#[path = "jordan_eigen_qp.rs"]
mod jordan_eigen_qp;
#[path = "jordan_fields.rs"]
mod jordan_fields;
#[path = "jordan_generic.rs"]
mod jordan_generic;
#[path = "jordan_primary.rs"]
mod jordan_primary;
#[path = "jordan_real_qp.rs"]
mod jordan_real_qp;
#[path = "latex.rs"]
mod latex;
#[path = "layers.rs"]
mod layers;
#[path = "library_api.rs"]
mod library_api;
#[path = "linalg_fields.rs"]
mod linalg_fields;
#[path = "margins.rs"]
mod margins;
#[path = "margins_fields.rs"]
mod margins_fields;
#[path = "matrix_dixon.rs"]
mod matrix_dixon;
#[path = "matrix_generic.rs"]
mod matrix_generic;
#[path = "matrix_modular.rs"]
mod matrix_modular;
#[path = "matrix_quadratic.rs"]
mod matrix_quadratic;
#[path = "matrix_rational.rs"]
mod matrix_rational;
#[path = "mechanical.rs"]
mod mechanical;
#[path = "memory_budget.rs"]
mod memory_budget;
#[path = "mnf_scale.rs"]
mod mnf_scale;
#[path = "mpoly.rs"]
mod mpoly;
#[path = "mpoly_gcd.rs"]
mod mpoly_gcd;
#[path = "multibody.rs"]
mod multibody;
#[path = "multibody_examples.rs"]
mod multibody_examples;
#[path = "over_fields.rs"]
mod over_fields;
#[path = "pencil.rs"]
mod pencil;
#[path = "pencil_descriptor.rs"]
mod pencil_descriptor;
#[path = "pencil_published.rs"]
mod pencil_published;
#[path = "plain_matrix.rs"]
mod plain_matrix;
#[path = "plots.rs"]
mod plots;
#[path = "poly_factor.rs"]
mod poly_factor;
#[path = "qp_conditions.rs"]
mod qp_conditions;
#[path = "qp_det_budget.rs"]
mod qp_det_budget;
#[path = "qp_kernels.rs"]
mod qp_kernels;
#[path = "qp_scale.rs"]
mod qp_scale;
#[path = "qp_scale_kernels.rs"]
mod qp_scale_kernels;
#[path = "quadratic_kernels.rs"]
mod quadratic_kernels;
#[path = "readable_text.rs"]
mod readable_text;
#[path = "realization.rs"]
mod realization;
#[path = "realization_planted.rs"]
mod realization_planted;
#[path = "reserved_names.rs"]
mod reserved_names;
#[path = "response_free.rs"]
mod response_free;
#[path = "response_modal.rs"]
mod response_modal;
#[path = "rest22.rs"]
mod rest22;
#[path = "robustness.rs"]
mod robustness;
#[path = "root_locus.rs"]
mod root_locus;
#[path = "scale_chain.rs"]
mod scale_chain;
#[path = "scale_dense.rs"]
mod scale_dense;
#[path = "scale_g.rs"]
mod scale_g;
#[path = "scale_kernels.rs"]
mod scale_kernels;
#[path = "scb.rs"]
mod scb;
#[path = "slowpaths.rs"]
mod slowpaths;
#[path = "steps.rs"]
mod steps;
#[path = "steps_descriptor.rs"]
mod steps_descriptor;
#[path = "steps_discrete.rs"]
mod steps_discrete;
#[path = "steps_forms.rs"]
mod steps_forms;
#[path = "steps_jordan_restriction.rs"]
mod steps_jordan_restriction;
#[path = "steps_modes_fields.rs"]
mod steps_modes_fields;
#[path = "steps_normalize.rs"]
mod steps_normalize;
#[path = "steps_qp_forms.rs"]
mod steps_qp_forms;
#[path = "steps_systems.rs"]
mod steps_systems;
#[path = "study.rs"]
mod study;
#[path = "study_classes.rs"]
mod study_classes;
#[path = "symbolic.rs"]
mod symbolic;
#[path = "symbolic_scb.rs"]
mod symbolic_scb;
#[path = "symjordan.rs"]
mod symjordan;
#[path = "system_fields.rs"]
mod system_fields;
#[path = "toolbox.rs"]
mod toolbox;

/// Every `tests/*.rs` file (other than this one) is mounted above: Cargo's automatic test
/// discovery is off (`autotests = false`), so an unlisted file would silently not run.
#[test]
fn every_test_file_is_a_module() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let this = include_str!("all.rs");
    for e in std::fs::read_dir(&dir).unwrap() {
        let name = e.unwrap().file_name().into_string().unwrap();
        if name.ends_with(".rs") && name != "all.rs" {
            let stem = name.trim_end_matches(".rs");
            assert!(
                this.contains(&format!("#[path = \"{name}\"]\nmod {stem};")),
                "tests/{name} is not a module of tests/all.rs"
            );
        }
    }
}
