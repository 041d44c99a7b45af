//! The memory limit where it is kept: Lua's allocator. A graded run's limit is mlua's
//! allocator limit; a request it refuses becomes a "not enough memory" error, which Lua code
//! can catch (`pcall`) or replace (a `<close>` variable's `__close` that raises — Lua 5.4
//! closes with the error and takes the handler's in its place). Catching was closed where the
//! error passes (the sandbox's protected calls and `__close` guards), but a handler can be
//! installed in more ways than any guard can follow (a metatable with a metatable of its own,
//! an `__index` chain copied in, a coroutine's way out). So the allocator itself reports every
//! refusal to the run's [`Budget`] ([`Budget::refused`], [`Budget::granted`]): from the failed
//! allocation on the run has passed the memory limit, whatever the Lua code then does — the
//! instruction hook and every protected call raise the verdict again, and the verdict is the
//! memory limit.
//!
//! The wrapper sits in front of mlua's own allocator (which keeps the limit and the count):
//! it calls it and watches what it answers. [`Watch::remove`] puts mlua's back when the run is
//! over, so the grader's own work afterwards is mlua's as before.

use crate::core::budget::Budget;
use mlua::ffi;
use std::os::raw::c_void;
use std::sync::Arc;

/// What the wrapper needs: mlua's allocator and its data, and the run's budget.
struct Inner {
    alloc: ffi::lua_Alloc,
    ud: *mut c_void,
    budget: Arc<Budget>,
}

/// The allocator wrapper installed in one Lua state (see the module's documentation).
pub struct Watch {
    /// Leaked while installed: Lua calls the wrapper with it until [`Watch::remove`], and
    /// `lua_close` may still call it if the state is dropped first (a few words per run).
    inner: *mut Inner,
}

// SAFETY: `inner` is only read by the allocator, which Lua calls under mlua's lock of the
// state, and by `remove`, which takes the same lock.
unsafe impl Send for Watch {}
unsafe impl Sync for Watch {}

/// Lua's allocator contract (`lua_Alloc`, Lua 5.4 manual §4.6): `nsize == 0` frees; otherwise
/// allocate or reallocate, NULL when refused. When `ptr` is NULL, `osize` is the kind of
/// object, not a size.
unsafe extern "C" fn watched(ud: *mut c_void, ptr: *mut c_void, osize: usize, nsize: usize) -> *mut c_void {
    // SAFETY: `ud` is the `Inner` installed with this function; it outlives the state's use.
    let inner = unsafe { &*(ud as *const Inner) };
    // SAFETY: mlua's allocator with its own data, as Lua would have called it.
    let r = unsafe { (inner.alloc)(inner.ud, ptr, osize, nsize) };
    let old = if ptr.is_null() { 0 } else { osize };
    if nsize > old {
        let a = (ptr as usize, osize, nsize);
        if r.is_null() {
            inner.budget.refused(a);
        } else if inner.budget.has_suspect() {
            inner.budget.granted(a);
        }
    }
    r
}

impl Watch {
    /// Puts the wrapper in front of `lua`'s allocator, reporting to `budget`.
    pub fn install(lua: &mlua::Lua, budget: Arc<Budget>) -> mlua::Result<Watch> {
        let mut watch = None;
        // SAFETY: `exec_raw` holds mlua's lock of the state; the allocator is swapped while no
        // allocation is under way, and the old one is kept to be called and put back.
        unsafe {
            lua.exec_raw::<()>((), |state| {
                let mut ud = std::ptr::null_mut();
                let alloc = ffi::lua_getallocf(state, &mut ud);
                let inner = Box::into_raw(Box::new(Inner { alloc, ud, budget }));
                ffi::lua_setallocf(state, watched, inner as *mut c_void);
                watch = Some(Watch { inner });
            })?;
        }
        watch.ok_or(mlua::Error::MemoryControlNotAvailable)
    }

    /// Puts mlua's allocator back (the memory limit is then mlua's to change again).
    pub fn remove(&self, lua: &mlua::Lua) -> mlua::Result<()> {
        let inner = self.inner;
        // SAFETY: as in `install`; `inner` stays allocated (see [`Watch::inner`]).
        unsafe {
            lua.exec_raw::<()>((), |state| {
                let mut ud = std::ptr::null_mut();
                ffi::lua_getallocf(state, &mut ud);
                if ud == inner as *mut c_void {
                    ffi::lua_setallocf(state, (*inner).alloc, (*inner).ud);
                }
            })
        }
    }
}
