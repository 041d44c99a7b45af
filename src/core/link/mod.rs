//! Transports, apart from codecs: pseudo-terminals (the simulators serve serial protocols on
//! them), serial ports, TCP. Drivers take any byte stream, so the same driver code runs on a
//! real port, a pty served by the simulator, or an in-memory pipe in tests.

pub mod async_pty;
pub mod fd_stream;
pub mod pty;
pub mod traced;
