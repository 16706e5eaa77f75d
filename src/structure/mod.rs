pub mod mechanical;
