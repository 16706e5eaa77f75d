pub mod fraction_free;
pub mod modular;
