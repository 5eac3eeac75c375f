// NASA PolyCARP's detectors (its Java version) timed on a plain workload file
// (polyguard's `uniform_workload --plain`), the same way as pc_speed.cpp and polyguard's
// `workload_speed` example; scripts/polycarp-speed compiles it with PolyCARP's Java
// sources (not part of this repository) and runs it beside them (docs/performance.md,
// "Against PolyCARP").
//
// The groups call the same PolyCARP functions as pc_speed.cpp (see there). The method is
// the same too (the median round by the thread's CPU clock and by the wall clock), with
// warm-up passes that matter here: the JIT compiles the detectors during the WARMUP
// untimed passes over every group, before any round is timed. The thread's CPU clock
// leaves out the collector's threads, the wall clock its pauses included. One line per
// group:
//   GROUP n CASES CPU_NS_PER_CALL WALL_NS_PER_CALL ANSWERS
// Options: --rounds N (30), --repeat R (10), --warmup W (5).

import gov.nasa.larcfm.ACCoRD.Polycarp3D;
import gov.nasa.larcfm.ACCoRD.PolycarpDetection;
import gov.nasa.larcfm.Util.MovingPolygon2D;
import gov.nasa.larcfm.Util.MovingPolygon3D;
import gov.nasa.larcfm.Util.Vect2;
import gov.nasa.larcfm.Util.Vect3;
import gov.nasa.larcfm.Util.Velocity;

import java.io.BufferedReader;
import java.io.FileReader;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

public class PcSpeed {
  static final int SAME = 0, DIFF = 1, SLAB = 2;

  static final class Case {
    double t, buff, fac, sz, vz, pmin, pmax, vsp;
    Vect2 s, v;
    ArrayList<Vect2> verts = new ArrayList<>(), vels = new ArrayList<>();
    MovingPolygon2D mp2;
    MovingPolygon3D mp3;
    Vect3 s3;
    Velocity v3;
  }

  static final class Group {
    String name;
    int n, kind;
    List<Case> cases = new ArrayList<>();
  }

  // The sink: every answer is added to it, so no call can be dropped.
  static volatile long sink;

  static boolean detect(int kind, Case c) {
    switch (kind) {
      case SAME:
        return PolycarpDetection.Static_Collision_Detector(0.0, c.t, c.verts, c.vels.get(0), c.s, c.v, c.buff, true);
      case DIFF:
        return PolycarpDetection.Collision_Detector(0.0, c.t, c.mp2, c.s, c.v, c.buff, c.fac, true);
      default:
        return Polycarp3D.entranceDetection(c.s3, c.v3, c.mp3, 0.0, c.t, c.buff, c.fac, false);
    }
  }

  static long pass(Group g, int reps) {
    long hits = 0;
    for (int r = 0; r < reps; r++) {
      for (Case c : g.cases) {
        if (detect(g.kind, c)) hits++;
      }
    }
    sink += hits;
    return hits;
  }

  static double median(double[] x) {
    double[] y = x.clone();
    Arrays.sort(y);
    return y[y.length / 2];
  }

  static void fail(String msg) {
    System.err.println("PcSpeed: " + msg);
    System.exit(2);
  }

  static List<Group> readGroups(String path) throws IOException {
    List<Group> groups = new ArrayList<>();
    try (BufferedReader in = new BufferedReader(new FileReader(path))) {
      String line;
      int lineno = 0;
      while ((line = in.readLine()) != null) {
        lineno++;
        String[] f = line.trim().split("\\s+");
        if (f[0].isEmpty() || f[0].startsWith("#")) continue;
        int n;
        try {
          n = Integer.parseInt(f[1]);
        } catch (RuntimeException e) {
          fail(path + ":" + lineno + ": bad line");
          return groups;
        }
        if (n < 3 || f.length != 14 + 4 * n) fail(path + ":" + lineno + ": bad line");
        double[] x = new double[f.length];
        for (int i = 2; i < f.length; i++) {
          try {
            x[i] = Double.parseDouble(f[i]);
          } catch (NumberFormatException e) {
            fail(path + ":" + lineno + ": " + f[i] + " is not a number");
          }
        }
        Case c = new Case();
        c.t = x[2];
        c.buff = x[3];
        c.fac = x[4];
        c.s = new Vect2(x[5], x[6]);
        c.v = new Vect2(x[7], x[8]);
        c.sz = x[9];
        c.vz = x[10];
        c.pmin = x[11];
        c.pmax = x[12];
        c.vsp = x[13];
        for (int k = 0; k < n; k++) {
          c.verts.add(new Vect2(x[14 + 2 * k], x[15 + 2 * k]));
          c.vels.add(new Vect2(x[14 + 2 * n + 2 * k], x[15 + 2 * n + 2 * k]));
        }
        int kind;
        if (f[0].equals("static")) kind = SAME;
        else if (f[0].equals("warping")) kind = DIFF;
        else if (f[0].equals("3d-static") || f[0].equals("3d-warping")) kind = SLAB;
        else {
          fail(path + ":" + lineno + ": unknown group " + f[0]);
          return groups;
        }
        c.mp2 = new MovingPolygon2D(c.verts, c.vels, c.t);
        c.mp3 = new MovingPolygon3D(c.mp2, c.vsp, c.pmin, c.pmax);
        c.s3 = new Vect3(x[5], x[6], c.sz);
        c.v3 = Velocity.mkVxyz(x[7], x[8], c.vz);
        Group g = null;
        for (Group h : groups) {
          if (h.name.equals(f[0]) && h.n == n) g = h;
        }
        if (g == null) {
          g = new Group();
          g.name = f[0];
          g.n = n;
          g.kind = kind;
          groups.add(g);
        }
        g.cases.add(c);
      }
    }
    return groups;
  }

  public static void main(String[] args) throws IOException {
    String file = null;
    int rounds = 30, reps = 10, warmup = 5;
    String usage = "usage: PcSpeed FILE [--rounds N] [--repeat R] [--warmup W]";
    for (int i = 0; i < args.length; i++) {
      String a = args[i];
      if ((a.equals("--rounds") || a.equals("--repeat") || a.equals("--warmup")) && i + 1 < args.length) {
        int v = Integer.parseInt(args[++i]);
        if (a.equals("--rounds")) rounds = Math.max(v, 1);
        else if (a.equals("--repeat")) reps = Math.max(v, 1);
        else warmup = Math.max(v, 0);
      } else if (file == null && !a.startsWith("--")) {
        file = a;
      } else {
        fail(usage);
      }
    }
    if (file == null) fail(usage);
    ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    if (!threads.isCurrentThreadCpuTimeSupported()) fail("the thread CPU clock cannot be read");
    threads.setThreadCpuTimeEnabled(true);
    List<Group> groups = readGroups(file);
    for (int w = 0; w < warmup; w++) {
      for (Group g : groups) pass(g, reps);
    }
    StringBuilder out = new StringBuilder();
    for (Group g : groups) {
      StringBuilder answers = new StringBuilder();
      for (Case c : g.cases) answers.append(detect(g.kind, c) ? '1' : '0');
      double calls = (double) reps * g.cases.size();
      double[] cpu = new double[rounds], wall = new double[rounds];
      for (int r = 0; r < rounds; r++) {
        long c0 = threads.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        pass(g, reps);
        long t1 = System.nanoTime();
        long c1 = threads.getCurrentThreadCpuTime();
        cpu[r] = (c1 - c0) / calls;
        wall[r] = (t1 - t0) / calls;
      }
      out.append(String.format(Locale.ROOT, "%s %d %d %.1f %.1f %s%n", g.name, g.n,
          g.cases.size(), median(cpu), median(wall), answers));
    }
    System.out.print(out);
  }
}
