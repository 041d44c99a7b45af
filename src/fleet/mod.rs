//! Fleets at work: the concurrent runner ([`run`]: one command line or script on every member
//! of a fleet at once) and the table of its results ([`report`]). These run shell commands, so
//! they are a front end; what a fleet *is* (`[fleets.NAME]` in the profile file, its members and
//! their `{FIRST..LAST}` ranges) is read with the profiles, [`crate::profile::fleet`], and
//! re-exported here.

pub mod report;
pub mod run;

pub use crate::profile::fleet::*;
