//! The shell's `lab` command reaches the labs through [`crate::shell::LabHook`] (labs sit above
//! the shell: a lab grades with Lua and shells of its own); this is that hook, installed by the
//! cli on its shell.

use crate::core::Result;
use crate::output::Outcome;
use crate::shell::{LabHook, Shell};
use std::path::{Path, PathBuf};

/// The labs of this module, for the shell.
pub struct Labs;

impl LabHook for Labs {
    fn new_lab(&self, dir: &Path) -> Result<Outcome> {
        super::new_lab(dir)
    }

    fn check(&self, lab: &Path) -> Result<(Outcome, String, bool)> {
        super::check(lab)
    }

    fn default_jobs(&self) -> usize {
        super::runner::default_jobs()
    }

    fn grade(
        &self,
        lab: &Path,
        submissions: &[PathBuf],
        jobs: usize,
    ) -> Result<(String, Outcome, Vec<serde_json::Value>)> {
        let (lab, reports) = super::grade(lab, submissions, jobs)?;
        let (head, o) = super::summary(&lab, &reports);
        Ok((head, o, reports.iter().map(super::report_json).collect()))
    }
}

/// Lets `shell` run `lab …`.
pub fn install(shell: &mut Shell) {
    shell.labs = Some(std::sync::Arc::new(Labs));
}
