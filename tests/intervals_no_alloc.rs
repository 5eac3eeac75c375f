//! `intervals::intervals_into` and `fence::detect_exit` allocate nothing: a counting
//! global allocator, armed on this thread only, sees no allocation while they run on
//! cases of every kind (2D and 3D, static, translating and warping, more edges than the
//! scan keeps on its stack, an output slice too short, a case outside the domain).

use polyguard::entry::Heights;
use polyguard::fence::detect_exit;
use polyguard::intervals::{intervals_into, End, Relation, Separation, Span};
use polyguard::Vect2;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::sync::atomic::{AtomicUsize, Ordering};

/// The system allocator, counting the allocations of threads that armed it.
struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    static ARMED: Cell<bool> = const { Cell::new(false) };
}

// SAFETY: every call is passed on to the system allocator unchanged; the count is a
// side effect that allocates nothing.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if ARMED.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        System.alloc(layout)
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if ARMED.with(Cell::get) {
            ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
        }
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// A regular n-gon of radius r about the origin, counterclockwise.
fn ngon(n: usize, r: f64) -> Vec<Vect2> {
    (0..n)
        .map(|k| {
            let a = k as f64 / n as f64 * std::f64::consts::TAU;
            Vect2::new(r * a.cos(), r * a.sin())
        })
        .collect()
}

#[test]
fn the_slice_forms_allocate_nothing() {
    // Every input is built before the allocator is armed.
    let shapes: Vec<(Vec<Vect2>, Vec<Vect2>)> = [5usize, 12, 100]
        .iter()
        .flat_map(|&n| {
            let p = ngon(n, 10.0);
            let still = vec![Vect2::ZERO; n];
            let drift = vec![Vect2::new(0.5, 0.25); n];
            let warp: Vec<Vect2> = p.iter().map(|q| q.scale(0.02)).collect();
            [(p.clone(), still), (p.clone(), drift), (p, warp)]
        })
        .collect();
    let z = Heights {
        sz: 5.0,
        vz: 1.0,
        bottom: 0.0,
        top: 10.0,
        vsp: 0.0,
    };
    let blank = Span {
        start: End::at(0.0),
        end: End::at(0.0),
        certain: false,
    };
    let mut out = [blank; 2];
    let mut answers = 0usize;
    ARMED.with(|a| a.set(true));
    for (p, vels) in &shapes {
        for heights in [None, Some(z)] {
            for (s, v) in [
                (Vect2::new(-30.0, 1.0), Vect2::new(4.0, 0.1)),
                (Vect2::new(0.0, 0.0), Vect2::new(1.0, 0.5)),
                (Vect2::new(f64::NAN, 0.0), Vect2::ZERO),
            ] {
                for relation in Relation::ALL {
                    let sep = Separation { d: 1.0, h: 0.5 };
                    let r = intervals_into(15.0, s, v, p, vels, heights, relation, sep, &mut out);
                    answers += r.unwrap_or_else(|o| o.needed_at_least);
                }
                answers += usize::from(detect_exit(
                    15.0,
                    s,
                    v,
                    p,
                    vels,
                    heights,
                    Separation { d: 1.0, h: 0.5 },
                ));
            }
        }
    }
    ARMED.with(|a| a.set(false));
    assert!(answers > 0);
    assert_eq!(
        ALLOCATIONS.load(Ordering::Relaxed),
        0,
        "allocations while armed"
    );
}
