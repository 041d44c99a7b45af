//! What a servo object write changes, stated before it is sent so the session's write rules
//! (a profile's `read_only`/`allow`, `--read-only`) can refuse it whole: the servo family
//! computes its own change lists from its frame codec and object table, and the write guard
//! only checks them (`core::device::Change`), knowing no family.
//!
//! - An object write changes that object, named as the drive's operands name it
//!   (`controlword`, `2FF0.09/u32`).
//! - A hand-made frame (`servo raw`) changes what its function code says (Kinco servo
//!   RS232 protocol, spec kinco-servo.md: 0x23/0x2B/0x2F write 4/2/1 bytes, 0x40/0x43/0x4B/0x4F
//!   read): a write code writes the frame's object, a read code changes nothing, and any
//!   other code is an action the guard cannot see into, so a write rule refuses it.

use super::frame::{func, FRAME_LEN};
use super::objects::{self, ObjRef};
use crate::core::device::Change;
use crate::core::DataType;

/// The change a write of `obj` makes.
pub fn write(obj: ObjRef) -> Change {
    Change::Write(obj.to_operand())
}

/// The changes a hand-made frame makes: none for a read, the object's write for a write
/// code, and an action named by its function code for any other code.
pub fn frame(bytes: &[u8; FRAME_LEN]) -> Vec<Change> {
    let b = bytes;
    let (index, sub) = (u16::from_le_bytes([b[2], b[3]]), b[4]);
    let obj = match objects::lookup(index, sub) {
        Some(o) => ObjRef::of(o),
        None => ObjRef { index, sub, dtype: DataType::DWord },
    };
    match b[1] {
        func::READ | func::READ_1 | func::READ_2 | func::READ_4 => Vec::new(),
        func::WRITE_1 | func::WRITE_2 | func::WRITE_4 => vec![write(obj)],
        code => {
            let what = format!("raw frame with function code 16#{code:02X}");
            vec![Change::Action { what: what.clone(), touches: vec![what] }]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::servo::frame::{Frame, Size};

    #[test]
    fn a_frame_changes_what_its_function_code_says() {
        assert!(frame(&Frame::read(1, 0x6041, 0).to_bytes()).is_empty());
        let w = frame(&Frame::write(1, 0x6040, 0, Size::B2, 6).to_bytes());
        assert_eq!(w, vec![write(ObjRef::of(objects::named("controlword")))]);
        let mut odd = Frame::read(1, 0x6041, 0).to_bytes();
        odd[1] = 0x99;
        match frame(&odd).as_slice() {
            [Change::Action { what, touches }] => {
                assert_eq!(what, "raw frame with function code 16#99");
                assert_eq!(touches, std::slice::from_ref(what));
            }
            other => panic!("{other:?}"),
        }
    }
}
