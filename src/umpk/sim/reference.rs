//! Reference lab programs built into the simulator: the teacher's solution of a lab, for
//! rehearsing a grading script through the real-time monitor before students' programs run.
//! They are ordinary [`Runner`]s on the UMPK's own timer and counter semantics
//! ([`super::logic`]), so a grading script that passes on a reference program checks the
//! same behaviour an IL program of the lab must show. One table, [`REFERENCES`].

use super::logic::{FnRunner, Group, Logic, Runner, Scan};

/// One reference program.
pub struct Reference {
    pub name: &'static str,
    pub description: &'static str,
    /// Sets timer presets and counter ratios, and returns the program.
    pub build: fn(&mut Logic) -> Box<dyn Runner>,
}

/// Every reference program.
pub static REFERENCES: &[Reference] = &[Reference {
    name: "lab1",
    description: "start/stop latch I0/I1 → Q0 (marker M0); on-delay T0 2.0 s (group 1, 20 × 0.1 s) after Q0 → Q1; \
                  counter C0 divides I2 by 4 → Q2 (pulse as long as the input pulse), reset by stop I1",
    build: lab1,
}];

fn lab1(logic: &mut Logic) -> Box<dyn Runner> {
    logic.set_timer(0, Group::Ms100, 20).expect("T0 exists on every model");
    logic.set_ratio(0, 4).expect("C0 exists on every model");
    Box::new(FnRunner {
        name: "lab1 (reference)".into(),
        f: |s: &mut Scan<'_>| {
            let (start, stop) = (s.io.input(0), s.io.input(1));
            let run = (start || s.io.output(0)) && !stop;
            s.io.set_output(0, run);
            s.io.set_marker(0, run);
            let delayed = s.timer(0, run);
            s.io.set_output(1, delayed);
            let pulse = s.counter(0, s.io.input(2), stop);
            s.io.set_output(2, pulse);
        },
    })
}

/// The reference program called `name`.
pub fn find(name: &str) -> Option<&'static Reference> {
    REFERENCES.iter().find(|r| r.name.eq_ignore_ascii_case(name))
}

/// `lab1` for messages.
pub fn names() -> String {
    REFERENCES.iter().map(|r| r.name).collect::<Vec<_>>().join(", ")
}
