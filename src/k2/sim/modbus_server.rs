//! The simulated K2 as a real Modbus server (`plcsh sim serve`): any Modbus client — an
//! HMI, mbpoll, pymodbus, plcsh's own wire driver — can read and write a [`K2Sim`] over
//! Modbus TCP, Modbus RTU on a pseudo-terminal, or RTU over TCP.
//!
//! The request handling ([`K2Service::handle`]) answers through the same map the driver
//! asks with ([`crate::k2::modbus_map`]): function codes 1, 2, 3, 4, 5, 6, 15, 16; the
//! manual's per-request limits (read bits ≤ 1600, write bits ≤ 800, read/write words ≤ 100,
//! §3.2.1) answered with *illegal data value*; a request outside one area with *illegal data
//! address*; any other function with *illegal function*. A request for another unit id gets
//! no reply at all, as from a real RTU slave (unit 0, broadcast, is executed without a
//! reply). The transports' loops that serve it (connection limit, idle timeout, one decoder for
//! every transport, silence-based RTU framing) are in [`super::modbus_net`], which uses this
//! file's [`K2Service`].
//!
//! Scans: a K2 serves its Modbus slave ports between program scans. Before each request the
//! server brings the simulation up to the clock ([`K2Sim::advance`]), which runs whatever the
//! scans since the last request did — the pulse outputs, the counters, and the programs in
//! the simulated CPU (`k2::sim::program`: a user program, the helper with `--agent`), scan by
//! scan. So each request sees memory as a PLC would between two scans.
//!
//! Injected faults ([`crate::k2::sim::fault`]) act here, on every transport: no reply, an
//! exception, a late reply; a corrupted CRC on RTU; a dropped connection on TCP.

use crate::k2::instr::EventKind;
use crate::k2::modbus_map::{self, Exception, Table};
use crate::k2::operand::Area;
use crate::k2::sim::fault::FaultKind;
use crate::k2::sim::K2Sim;
use std::future::{ready, Ready};
use std::sync::{Arc, Mutex, MutexGuard};
use tokio_modbus::server::Service;
use tokio_modbus::{ExceptionCode, Request, Response, SlaveRequest};

/// The K2 behind a Modbus server: the shared simulator and the unit id it answers to.
/// Cheap to clone (one per connection).
#[derive(Clone)]
pub struct K2Service {
    sim: Arc<Mutex<K2Sim>>,
    unit: u8,
}

/// A request served, with the injected fault that acted on it (if any), for the transport
/// to finish (corrupt the CRC, drop the connection).
pub struct Served {
    pub reply: Option<Result<Response, ExceptionCode>>,
    pub fault: Option<FaultKind>,
}

fn lock<T: ?Sized>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

impl From<Exception> for ExceptionCode {
    fn from(e: Exception) -> ExceptionCode {
        ExceptionCode::new(e as u8)
    }
}

impl K2Service {
    pub fn new(sim: Arc<Mutex<K2Sim>>, unit: u8) -> K2Service {
        K2Service { sim, unit }
    }

    pub fn unit(&self) -> u8 {
        self.unit
    }

    /// Serves one request addressed to `unit`. `None`: no reply (another unit id, or a
    /// broadcast).
    pub fn handle(&self, unit: u8, req: &Request<'_>) -> Option<Result<Response, ExceptionCode>> {
        self.handle_with_faults(unit, req).reply
    }

    /// Serves one request, letting injected faults act on it (logged as events).
    pub fn handle_with_faults(&self, unit: u8, req: &Request<'_>) -> Served {
        let (reply, fault) = self.with_faults(unit, req, |sim| serve(sim, req));
        Served { reply, fault }
    }

    /// Serves one request as [`Self::handle_with_faults`] does, appending the reply PDU
    /// (function code and data, or the exception) to `out`: a read of registers is one slice
    /// copy of the memory image, which holds them in the byte order they travel in.
    /// Returns whether a reply was written, and the injected fault that acted.
    pub fn handle_into(&self, unit: u8, req: &Request<'_>, out: &mut Vec<u8>) -> (bool, Option<FaultKind>) {
        let fc = req.function_code().value();
        let (reply, fault) = self.with_faults(unit, req, |sim| serve_into(sim, req, out));
        match reply {
            None => (false, fault),
            Some(Ok(())) => (true, fault),
            Some(Err(e)) => {
                out.extend_from_slice(&[fc | 0x80, u8::from(e)]);
                (true, fault)
            }
        }
    }

    /// The unit check, the clock, and the injected faults around serving `req` with `serve`.
    fn with_faults<R>(
        &self,
        unit: u8,
        req: &Request<'_>,
        serve: impl FnOnce(&mut K2Sim) -> Result<R, Exception>,
    ) -> (Option<Result<R, ExceptionCode>>, Option<FaultKind>) {
        if unit != self.unit && unit != 0 {
            return (None, None);
        }
        let mut sim = lock(&self.sim);
        sim.advance();
        let mut fault = None;
        if !sim.faults.is_empty() {
            let touched = touched(&sim, req);
            let now = sim.last;
            if let Some((id, kind)) = sim.faults.on_request(now, &touched, true) {
                sim.events.extend(vec![(now, EventKind::Fault { id, fault: kind.code() })]);
                fault = Some(kind);
                match kind {
                    FaultKind::NoReply | FaultKind::Drop | FaultKind::PowerLoss => return (None, fault),
                    FaultKind::Exception { code } => {
                        return ((unit != 0).then_some(Err(ExceptionCode::new(code))), fault)
                    }
                    FaultKind::Late { ms } => {
                        // Wall time: the client's timeout runs on it. The simulator is unlocked meanwhile.
                        drop(sim);
                        std::thread::sleep(std::time::Duration::from_millis(ms));
                        sim = lock(&self.sim);
                        sim.advance();
                    }
                    _ => {}
                }
            }
        }
        let r = serve(&mut sim).map_err(ExceptionCode::from);
        ((unit != 0).then_some(r), fault)
    }
}

/// The area bytes a request touches (none when it is outside the map), for fault ranges.
fn touched(sim: &K2Sim, req: &Request<'_>) -> Vec<(Area, u32, u32)> {
    let (table, addr, count) = match req {
        Request::ReadCoils(a, n) | Request::ReadDiscreteInputs(a, n) => {
            (if matches!(req, Request::ReadCoils(..)) { Table::Coils } else { Table::DiscreteInputs }, *a, *n)
        }
        Request::ReadHoldingRegisters(a, n) => (Table::HoldingRegisters, *a, *n),
        Request::ReadInputRegisters(a, n) => (Table::InputRegisters, *a, *n),
        Request::WriteSingleCoil(a, _) => (Table::Coils, *a, 1),
        Request::WriteMultipleCoils(a, b) => (Table::Coils, *a, b.len() as u16),
        Request::WriteSingleRegister(a, _) => (Table::HoldingRegisters, *a, 1),
        Request::WriteMultipleRegisters(a, w) => (Table::HoldingRegisters, *a, w.len() as u16),
        _ => return Vec::new(),
    };
    let Ok((region, off)) = modbus_map::resolve(sim.space(), table, addr, count.max(1)) else { return Vec::new() };
    let n = u32::from(count.max(1));
    let (first, last) = if table.is_bits() { (off / 8, (off + n - 1) / 8) } else { (2 * off, 2 * (off + n) - 1) };
    vec![(region.area, first, last)]
}

/// The area bytes a request addresses, after the limit and bound checks.
fn area_of(sim: &K2Sim, fc: u8, table: Table, addr: u16, count: usize) -> Result<(Area, u32), Exception> {
    modbus_map::check_quantity(fc, count)?;
    let (region, off) = modbus_map::resolve(sim.space(), table, addr, count as u16)?;
    Ok((region.area, off))
}

fn read_bits(sim: &K2Sim, area: Area, off: u32, count: u16) -> Vec<bool> {
    let bytes = sim.mem.area(area);
    (off..off + count as u32).map(|b| (bytes[(b / 8) as usize] >> (b % 8)) & 1 != 0).collect()
}

fn write_bits(sim: &mut K2Sim, area: Area, off: u32, bits: &[bool]) {
    let bytes = sim.mem.area_mut(area);
    for (k, on) in bits.iter().enumerate() {
        let b = off + k as u32;
        let byte = &mut bytes[(b / 8) as usize];
        if *on {
            *byte |= 1 << (b % 8)
        } else {
            *byte &= !(1 << (b % 8))
        }
    }
}

fn read_words(sim: &K2Sim, area: Area, off: u32, count: u16) -> Vec<u16> {
    let bytes = sim.mem.area(area);
    let first = 2 * off as usize;
    bytes[first..first + 2 * count as usize].chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]])).collect()
}

fn write_words(sim: &mut K2Sim, area: Area, off: u32, words: &[u16]) {
    let bytes = sim.mem.area_mut(area);
    for (k, w) in words.iter().enumerate() {
        let at = 2 * (off as usize + k);
        bytes[at..at + 2].copy_from_slice(&w.to_be_bytes());
    }
}

/// Makes a store durable before its reply goes out (`K2Sim::commit_store`); a state file
/// that cannot be written is the device failing (exception 04), never a silent success.
fn durable(sim: &mut K2Sim, area: Area, lo: u32, hi: u32) -> Result<(), Exception> {
    sim.commit_store(area, lo, hi).map_err(|e| {
        eprintln!("plcsh: {e}");
        Exception::ServerDeviceFailure
    })
}

/// [`serve`] with the reply PDU appended to `out`; reads of registers copy the memory bytes
/// straight into it.
fn serve_into(sim: &mut K2Sim, req: &Request<'_>, out: &mut Vec<u8>) -> Result<(), Exception> {
    let (fc, table, a, n) = match req {
        Request::ReadHoldingRegisters(a, n) => (0x03, Table::HoldingRegisters, *a, *n),
        Request::ReadInputRegisters(a, n) => (0x04, Table::InputRegisters, *a, *n),
        _ => {
            let fc = req.function_code().value();
            out.extend_from_slice(&super::rtu_frame::encode_pdu(fc, &Ok(serve(sim, req)?)));
            return Ok(());
        }
    };
    let (area, off) = area_of(sim, fc, table, a, n as usize)?;
    let first = 2 * off as usize;
    out.extend_from_slice(&[fc, 2 * n as u8]);
    out.extend_from_slice(&sim.mem.area(area)[first..first + 2 * n as usize]);
    Ok(())
}

/// Serves one request on the simulator (the unit id was already checked).
fn serve(sim: &mut K2Sim, req: &Request<'_>) -> Result<Response, Exception> {
    use Table::*;
    Ok(match req {
        Request::ReadCoils(a, n) => {
            let (area, off) = area_of(sim, 0x01, Coils, *a, *n as usize)?;
            Response::ReadCoils(read_bits(sim, area, off, *n))
        }
        Request::ReadDiscreteInputs(a, n) => {
            let (area, off) = area_of(sim, 0x02, DiscreteInputs, *a, *n as usize)?;
            Response::ReadDiscreteInputs(read_bits(sim, area, off, *n))
        }
        Request::ReadHoldingRegisters(a, n) => {
            let (area, off) = area_of(sim, 0x03, HoldingRegisters, *a, *n as usize)?;
            Response::ReadHoldingRegisters(read_words(sim, area, off, *n))
        }
        Request::ReadInputRegisters(a, n) => {
            let (area, off) = area_of(sim, 0x04, InputRegisters, *a, *n as usize)?;
            Response::ReadInputRegisters(read_words(sim, area, off, *n))
        }
        Request::WriteSingleCoil(a, v) => {
            let (area, off) = area_of(sim, 0x05, Coils, *a, 1)?;
            write_bits(sim, area, off, &[*v]);
            durable(sim, area, off / 8, off / 8 + 1)?;
            Response::WriteSingleCoil(*a, *v)
        }
        Request::WriteMultipleCoils(a, bits) => {
            let (area, off) = area_of(sim, 0x0F, Coils, *a, bits.len())?;
            write_bits(sim, area, off, bits);
            durable(sim, area, off / 8, (off + bits.len() as u32).div_ceil(8))?;
            Response::WriteMultipleCoils(*a, bits.len() as u16)
        }
        Request::WriteSingleRegister(a, w) => {
            let (area, off) = area_of(sim, 0x06, HoldingRegisters, *a, 1)?;
            write_words(sim, area, off, &[*w]);
            durable(sim, area, 2 * off, 2 * off + 2)?;
            Response::WriteSingleRegister(*a, *w)
        }
        Request::WriteMultipleRegisters(a, words) => {
            let (area, off) = area_of(sim, 0x10, HoldingRegisters, *a, words.len())?;
            write_words(sim, area, off, words);
            durable(sim, area, 2 * off, 2 * (off + words.len() as u32))?;
            Response::WriteMultipleRegisters(*a, words.len() as u16)
        }
        _ => return Err(Exception::IllegalFunction),
    })
}

impl Service for K2Service {
    type Request = SlaveRequest<'static>;
    type Response = Option<Response>;
    type Exception = ExceptionCode;
    type Future = Ready<Result<Option<Response>, ExceptionCode>>;

    fn call(&self, req: SlaveRequest<'static>) -> Self::Future {
        // A `drop` fault closes the connection in the served loops (`modbus_net`); through
        // this interface it is no reply.
        let served = self.handle_with_faults(req.slave, &req.request);
        ready(match served.reply {
            None => Ok(None),
            Some(Ok(r)) => Ok(Some(r)),
            Some(Err(e)) => Err(e),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Clock;
    use crate::k2::sim;
    use std::borrow::Cow;
    use std::time::Duration;

    fn service(model: &str) -> K2Service {
        let s = sim::open(model, Clock::stepped()).unwrap();
        K2Service::new(Arc::new(Mutex::new(s)), 1)
    }

    fn ok(s: &K2Service, r: Request<'_>) -> Response {
        s.handle(1, &r).unwrap().unwrap()
    }

    fn err(s: &K2Service, r: Request<'_>) -> ExceptionCode {
        s.handle(1, &r).unwrap().unwrap_err()
    }

    #[test]
    fn registers_and_coils_reach_the_memory_image() {
        let s = service("K205-16DT");
        ok(&s, Request::WriteMultipleRegisters(150, Cow::Owned(vec![0x1234, 0x5678])));
        {
            let sim = lock(&s.sim);
            assert_eq!(&sim.mem.v[100..104], &[0x12, 0x34, 0x56, 0x78], "register 150 = VW100, S7 order");
        }
        assert_eq!(ok(&s, Request::ReadHoldingRegisters(151, 1)), Response::ReadHoldingRegisters(vec![0x5678]));
        assert_eq!(ok(&s, Request::ReadInputRegisters(150, 1)), Response::ReadInputRegisters(vec![0x1234]));
        ok(&s, Request::WriteSingleCoil(320 + 8 * 10 + 3, true));
        assert_eq!(lock(&s.sim).mem.m[10], 0b1000, "coil 403 = M10.3");
        ok(&s, Request::WriteMultipleCoils(1, Cow::Owned(vec![true, false, true])));
        assert_eq!(lock(&s.sim).mem.q[0], 0b1010);
        assert_eq!(
            ok(&s, Request::ReadDiscreteInputs(403, 1)),
            Response::ReadDiscreteInputs(vec![true]),
            "M is also discrete inputs 320…"
        );
    }

    #[test]
    fn limits_bounds_and_functions_get_their_exception_codes() {
        let s = service("K205-16DT");
        assert_eq!(err(&s, Request::ReadHoldingRegisters(100, 101)), ExceptionCode::IllegalDataValue);
        assert_eq!(err(&s, Request::ReadCoils(320, 1601)), ExceptionCode::IllegalDataValue);
        assert!(s.handle(1, &Request::ReadCoils(320, 1600)).unwrap().is_ok());
        assert_eq!(
            err(&s, Request::WriteMultipleCoils(320, Cow::Owned(vec![false; 801]))),
            ExceptionCode::IllegalDataValue
        );
        assert_eq!(
            err(&s, Request::WriteMultipleRegisters(100, Cow::Owned(vec![0; 101]))),
            ExceptionCode::IllegalDataValue
        );
        // V ends at register 2147 on the K205; 90 words of a 2-word area (§3.2.1's example).
        assert_eq!(err(&s, Request::ReadHoldingRegisters(2140, 10)), ExceptionCode::IllegalDataAddress);
        assert_eq!(err(&s, Request::ReadHoldingRegisters(50, 1)), ExceptionCode::IllegalDataAddress);
        assert_eq!(err(&s, Request::ReadInputRegisters(0, 1)), ExceptionCode::IllegalDataAddress, "K205: no AI");
        let ea = service("K209EA-50DX");
        assert_eq!(err(&ea, Request::ReadInputRegisters(0, 90)), ExceptionCode::IllegalDataAddress);
        assert!(ea.handle(1, &Request::ReadInputRegisters(0, 6)).unwrap().is_ok());
        assert_eq!(err(&s, Request::MaskWriteRegister(100, 0, 0)), ExceptionCode::IllegalFunction);
        assert_eq!(err(&s, Request::Custom(0x41, Cow::Owned(vec![]))), ExceptionCode::IllegalFunction);
    }

    #[test]
    fn replies_written_in_place_equal_the_encoded_responses() {
        let s = service("K205-16DT");
        {
            let mut sim = lock(&s.sim);
            for (k, b) in sim.mem.v.iter_mut().enumerate().take(300) {
                *b = (k * 29 + 3) as u8;
            }
        }
        let requests = [
            Request::ReadHoldingRegisters(100, 100),
            Request::ReadHoldingRegisters(151, 1),
            Request::ReadInputRegisters(150, 7),
            Request::ReadHoldingRegisters(100, 101),
            Request::ReadHoldingRegisters(2140, 10),
            Request::ReadCoils(320, 19),
            Request::WriteSingleRegister(100, 7),
            Request::MaskWriteRegister(100, 0, 0),
        ];
        for unit in [1, 2] {
            for r in &requests {
                let fc = r.function_code().value();
                let want = s.handle(unit, r).map(|reply| crate::k2::sim::rtu_frame::encode_pdu(fc, &reply));
                let mut out = vec![0xAA]; // what the transport put before the PDU stays
                let (replied, fault) = s.handle_into(unit, r, &mut out);
                assert_eq!(fault, None);
                assert_eq!(replied.then(|| out[1..].to_vec()), want, "unit {unit}: {r:?}");
                assert_eq!(out[0], 0xAA);
            }
        }
    }

    #[test]
    fn other_units_get_no_reply_and_broadcasts_write_silently() {
        let s = service("K205-16DT");
        assert!(s.handle(2, &Request::ReadHoldingRegisters(100, 1)).is_none());
        assert!(s.handle(0, &Request::WriteSingleRegister(100, 7)).is_none());
        assert_eq!(ok(&s, Request::ReadHoldingRegisters(100, 1)), Response::ReadHoldingRegisters(vec![7]));
    }

    #[test]
    fn served_faults_act_on_their_range_and_are_logged() {
        use crate::k2::sim::fault;
        let s = service("K205-16DT");
        {
            let mut sim = lock(&s.sim);
            for f in ["no-reply on VW0 times=1", "exception 4 on VW100..VW110", "bad-crc on MB0 times=1"] {
                sim.faults.add(&fault::parse(f).unwrap(), Duration::ZERO);
            }
        }
        assert!(s.handle(1, &Request::ReadHoldingRegisters(100, 1)).is_none(), "VW0 = register 100: no reply");
        assert!(s.handle(1, &Request::ReadHoldingRegisters(100, 1)).unwrap().is_ok(), "times=1");
        assert_eq!(err(&s, Request::ReadHoldingRegisters(152, 4)), ExceptionCode::new(4), "VW104…VW110");
        assert!(s.handle(1, &Request::ReadHoldingRegisters(140, 1)).unwrap().is_ok(), "VW80: outside");
        let served = s.handle_with_faults(1, &Request::ReadCoils(320, 8));
        assert_eq!(served.fault, Some(FaultKind::BadCrc), "M0.0…M0.7");
        assert!(served.reply.unwrap().is_ok(), "the reply goes out; the RTU framing corrupts it");
        let names: Vec<String> = lock(&s.sim).events.list().iter().map(|e| e.kind.name()).collect();
        assert_eq!(names, vec!["fault1", "fault2", "fault3"]);
    }
}
