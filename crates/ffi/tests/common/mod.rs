//! Helpers shared by the C interface's integration tests: the thread's last error
//! message and shorthands for the C structs.

use std::ffi::CStr;
use std::os::raw::c_char;
use std::ptr;

use polyguard_ffi::*;

/// This thread's last error message (`pg_last_error_message`).
pub fn message() -> String {
    let mut buf = [0 as c_char; 512];
    // SAFETY: buf holds 512 bytes.
    let rc = unsafe { pg_last_error_message(buf.as_mut_ptr(), buf.len()) };
    assert_eq!(rc, PG_OK);
    // SAFETY: NUL-terminated by pg_last_error_message.
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

/// Shorthand for a C vector.
pub fn v(x: f64, y: f64) -> PgVec2 {
    PgVec2 { x, y }
}

/// A 2D polygon over the caller's arrays (velocities NULL: at rest).
pub fn polygon(vertices: &[PgVec2], velocities: Option<&[PgVec2]>) -> PgPolygon {
    PgPolygon {
        vertices: vertices.as_ptr(),
        velocities: velocities.map_or(ptr::null(), <[PgVec2]>::as_ptr),
        n: vertices.len(),
        has_slab: 0,
        slab: PgSlab::default(),
    }
}
