// NASA PolyCARP's detectors timed on a plain workload file (polyguard's
// `uniform_workload --plain`), the same way as polyguard's `workload_speed` example
// times paper A's: scripts/polycarp-speed builds this file with PolyCARP's C++ sources
// (not part of this repository) in one LTO link and runs it beside the others
// (docs/performance.md, "Against PolyCARP").
//
// Each group calls the PolyCARP function that implements the paper function polyguard
// calls: `static` Static_Collision_Detector (detect_same_2D, a polygon with one velocity),
// `warping` Collision_Detector (detect_diff_2D), `3d-static` and `3d-warping`
// Polycarp3D::entranceDetection (detect_3D); all from time 0 to T, a conflict being
// "not definitely outside" (insideBad), no polygon check. PolyCARP's polygon objects are
// built once per case, outside the timing, as polyguard's are.
//
// The method: WARMUP untimed passes over every group; then, per group, ROUNDS timed
// rounds, each REPEAT passes over the group's cases; the figure is the median round's
// time per call (the upper middle of the sorted rounds), by the thread's CPU clock and
// by the wall clock (on a shared machine, the wall clock of a round also counts the time
// other work took the core). One line per group:
//   GROUP n CASES CPU_NS_PER_CALL WALL_NS_PER_CALL ANSWERS
// ANSWERS has one '1' (conflict) or '0' per case, in the file's order.
// Options: --rounds N (30), --repeat R (10), --warmup W (5).

#include "MovingPolygon2D.h"
#include "MovingPolygon3D.h"
#include "Polycarp3D.h"
#include "PolycarpDetection.h"
#include "Vect2.h"
#include "Vect3.h"
#include "Velocity.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <time.h>
#include <vector>

using namespace larcfm;

namespace {

// Keeps the compiler from dropping or hoisting a computation: the value is "used" and
// memory may have changed.
template <class T> inline void black_box(T const& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

enum Kind { SAME, DIFF, SLAB };

struct Case {
  double t, buff, fac;
  Vect2 s, v;
  double sz, vz, pmin, pmax, vsp;
  std::vector<Vect2> verts, vels;
  MovingPolygon2D mp2;  // warping: the moving polygon
  MovingPolygon3D mp3;  // 3D: the moving slab polygon
  Vect3 s3;
  Velocity v3;
};

struct Group {
  std::string name;
  int n;
  Kind kind;
  std::vector<Case> cases;
};

bool detect(Kind kind, const Case& c) {
  switch (kind) {
    case SAME:
      return PolycarpDetection::Static_Collision_Detector(0.0, c.t, c.verts, c.vels[0], c.s, c.v,
                                                          c.buff, true);
    case DIFF:
      return PolycarpDetection::Collision_Detector(0.0, c.t, c.mp2, c.s, c.v, c.buff, c.fac, true);
    default:
      return Polycarp3D::entranceDetection(c.s3, c.v3, c.mp3, 0.0, c.t, c.buff, c.fac, false);
  }
}

__attribute__((noinline)) long pass(const Group& g, int reps) {
  long hits = 0;
  for (int r = 0; r < reps; r++) {
    for (const Case& c : g.cases) {
      const Case* p = &c;
      black_box(p);
      bool hit = detect(g.kind, *p);
      black_box(hit);
      hits += hit;
    }
  }
  return hits;
}

[[noreturn]] void fail(const std::string& msg) {
  std::cerr << "pc_speed: " << msg << "\n";
  std::exit(2);
}

// This thread's CPU time in nanoseconds.
double thread_cpu_ns() {
  timespec ts;
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0) fail("the thread CPU clock cannot be read");
  return ts.tv_sec * 1e9 + ts.tv_nsec;
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x[x.size() / 2];
}

std::vector<Group> read_groups(const char* path) {
  std::ifstream in(path);
  if (!in) fail(std::string(path) + ": cannot open");
  std::vector<Group> groups;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    lineno++;
    std::istringstream f(line);
    std::string name;
    if (!(f >> name) || name[0] == '#') continue;
    int n;
    Case c;
    f >> n >> c.t >> c.buff >> c.fac;
    double sx, sy, vx, vy;
    f >> sx >> sy >> vx >> vy >> c.sz >> c.vz >> c.pmin >> c.pmax >> c.vsp;
    c.s = Vect2(sx, sy);
    c.v = Vect2(vx, vy);
    for (int k = 0; k < 2 * n; k++) {
      double x, y;
      f >> x >> y;
      (k < n ? c.verts : c.vels).push_back(Vect2(x, y));
    }
    std::string extra;
    if (!f || n < 3 || (f >> extra)) fail(std::string(path) + ":" + std::to_string(lineno) + ": bad line");
    Kind kind;
    if (name == "static") kind = SAME;
    else if (name == "warping") kind = DIFF;
    else if (name == "3d-static" || name == "3d-warping") kind = SLAB;
    else fail(std::string(path) + ":" + std::to_string(lineno) + ": unknown group " + name);
    c.mp2 = MovingPolygon2D(c.verts, c.vels, c.t);
    c.mp3 = MovingPolygon3D(c.mp2, c.vsp, c.pmin, c.pmax);
    c.s3 = Vect3(sx, sy, c.sz);
    c.v3 = Velocity::mkVxyz(vx, vy, c.vz);
    auto g = std::find_if(groups.begin(), groups.end(),
                          [&](const Group& x) { return x.name == name && x.n == n; });
    if (g == groups.end()) {
      groups.push_back(Group{name, n, kind, {}});
      g = groups.end() - 1;
    }
    g->cases.push_back(c);
  }
  return groups;
}

}  // namespace

int main(int argc, char** argv) {
  const char* file = nullptr;
  int rounds = 30, reps = 10, warmup = 5;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    if ((a == "--rounds" || a == "--repeat" || a == "--warmup") && i + 1 < argc) {
      int v = std::atoi(argv[++i]);
      if (a == "--rounds") rounds = std::max(v, 1);
      else if (a == "--repeat") reps = std::max(v, 1);
      else warmup = std::max(v, 0);
    } else if (!file && a.rfind("--", 0) != 0) {
      file = argv[i];
    } else {
      fail("usage: pc_speed FILE [--rounds N] [--repeat R] [--warmup W]");
    }
  }
  if (!file) fail("usage: pc_speed FILE [--rounds N] [--repeat R] [--warmup W]");
  std::vector<Group> groups = read_groups(file);
  for (int w = 0; w < warmup; w++)
    for (const Group& g : groups) black_box(pass(g, reps));
  for (const Group& g : groups) {
    std::string answers;
    for (const Case& c : g.cases) answers += detect(g.kind, c) ? '1' : '0';
    double calls = double(reps) * g.cases.size();
    std::vector<double> cpu, wall;
    for (int r = 0; r < rounds; r++) {
      double c0 = thread_cpu_ns();
      auto t0 = std::chrono::steady_clock::now();
      black_box(pass(g, reps));
      auto t1 = std::chrono::steady_clock::now();
      double c1 = thread_cpu_ns();
      cpu.push_back((c1 - c0) / calls);
      wall.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / calls);
    }
    std::printf("%s %d %zu %.1f %.1f %s\n", g.name.c_str(), g.n, g.cases.size(), median(cpu),
                median(wall), answers.c_str());
  }
  return 0;
}
