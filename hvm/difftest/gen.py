#!/usr/bin/env python3
"""Generates one differential-test program for the icecap HVM (hvm/difftest.sh).

   gen.py SEED COUNT OUT.java [EXPECTED.txt]

The program (class difftest.G<SEED>) has COUNT methods v0..v<COUNT-1>, each computing a random
int, long or double value from static fields (edge values included: 0, +-1, MIN/MAX, NaN,
infinities, -0.0; byte, short and char fields) through arithmetic, conversions, comparisons,
shifts, locals, loops, switches, arrays of every integral type, instance fields, calls to
compiled helpers with int, long and double parameters, calls between compiled and
interpreted methods (overloads named main, which icecap -aot never compiles), and calls of
synchronized methods (gates) that return a branch's result (a comparison or a ?: of int, long or
double; their monitor's unlock writes over the stack the VM gives it, patch 23), and returns its
bits as a long. Stored chars stay in 0-127: icecap keeps a char in 8 bits (a design choice of the
VM) and reads a char field or array element back sign-extended (128-255 come back negative;
not fixed yet, docs/HVM.md). Without EXPECTED the program's main does
nothing (HotSpot runs the v methods by reflection to make EXPECTED, one long per line); with it,
main (always interpreted) compares every value with HotSpot's, bit for bit (any NaN equals any
NaN), prints the index of each disagreement and exits non-zero if there was one.
"""
import random
import sys

INT_EDGE = ["0", "1", "-1", "2", "7", "-7", "31", "32", "33", "63", "64", "65", "127", "128", "-128", "255",
            "32767", "-32768", "65535", "0x12345678", "0x7fffffff", "(-0x7fffffff - 1)"]
LONG_EDGE = ["0L", "1L", "-1L", "3L", "-3L", "63L", "64L", "0x7fffffffL", "0x80000000L", "0xffffffffL",
             "0x100000000L", "0x123456789abcdefL", "0x7fffffffffffffffL", "(-0x7fffffffffffffffL - 1L)",
             "-0x5deece66dL"]
DBL_EDGE = ["0.0", "-0.0", "1.0", "-1.0", "0.5", "2.5", "-2.5", "1e-300", "1e300", "4.9e-324", "2147483647.5",
            "-2147483648.5", "9.3e18", "-9.3e18", "Double.NaN", "Double.POSITIVE_INFINITY",
            "Double.NEGATIVE_INFINITY", "3.141592653589793", "1e10", "0.1"]


class Gen:
    def __init__(self, seed):
        self.r = random.Random(seed)
        self.fields = []  # (type, name, init): static fields
        for t, edge, n in (("int", INT_EDGE, 8), ("long", LONG_EDGE, 8), ("double", DBL_EDGE, 8)):
            for k in range(n):
                self.fields.append((t, "%s%d" % (t[0], k), self.literal(t, edge)))
        # narrow statics, read as ints (edge values of their own type)
        for t, vals in (("byte", ["0", "1", "-1", "127", "-128", "100"]), ("short", ["0", "-1", "32767", "-32768", "1000"]),
                        ("char", ["0", "1", "127", "100", "'A'"])):
            for k in range(2):
                self.fields.append((t, "%s%d" % (t[0] + "f", k), "(%s) %s" % (t, self.r.choice(vals))))
        self.scope = []  # (type, name): parameters and locals of the method being generated
        self.helpers = []  # (return type, name) of the compiled helpers callable so far
        self.gates = []  # (return type, name, parameter count) of the synchronized methods of lk
        self.names = 0

    def literal(self, t, edge):
        r = self.r
        if r.random() < 0.6:
            return r.choice(edge)
        if t == "int":
            return str(r.randint(-2**31 + 1, 2**31 - 1))
        if t == "long":
            return "%dL" % r.randint(-2**63 + 1, 2**63 - 1)
        return repr(r.uniform(-1e6, 1e6) * 10 ** r.randint(-5, 5))

    def leaf(self, t):
        r = self.r
        local = [n for (tt, n) in self.scope if tt == t]
        if local and r.random() < 0.5:
            return r.choice(local)
        if r.random() < 0.12:
            return {"int": lambda: r.choice(INT_EDGE), "long": lambda: r.choice(LONG_EDGE),
                    "double": lambda: r.choice(DBL_EDGE)}[t]()
        if r.random() < 0.2:
            return "o." + {"int": r.choice(["i", "b", "s", "c"]), "long": "l", "double": "d"}[t]
        kinds = {"int": ("int", "byte", "short", "char"), "long": ("long",), "double": ("double",)}[t]
        return r.choice([f[1] for f in self.fields if f[0] in kinds])

    def expr(self, t, d):
        r = self.r
        if d <= 0 or r.random() < 0.2:
            return self.leaf(t)
        e = lambda tt: self.expr(tt, d - 1)
        k = r.random()
        if r.random() < 0.06 and self.helpers:
            calls = [n for (tt, n) in self.helpers if tt == t]
            if calls:
                return "%s(%s, %s, %s)" % (r.choice(calls), e("int"), e("long"), e("double"))
        if r.random() < 0.05 and self.gates:
            gate = r.choice([g for g in self.gates if g[0] in (t, "boolean")])
            args = ", ".join(e("int") for _ in range(gate[2]))
            if gate[0] == "boolean":
                return "(lk.%s(%s) ? %s : %s)" % (gate[1], args, e(t), e(t))
            return "lk.%s(%s)" % (gate[1], args)
        if t == "int":
            if k < 0.45:
                op = r.choice(["+", "-", "*", "&", "|", "^", "/", "%", "<<", ">>", ">>>"])
                if op in ("/", "%"):
                    return "(%s %s (%s | 1))" % (e("int"), op, e("int"))
                return "(%s %s %s)" % (e("int"), op, e("int"))
            if k < 0.55:
                return "(- %s)" % e("int")
            if k < 0.75:
                return r.choice(["(int) %s", "(byte) %s", "(char) %s", "(short) %s", "(int) (long) %s"]) % (
                    "(" + e(r.choice(["int", "long", "double"])) + ")")
            if k < 0.85:
                return "(%s ? %s : %s)" % (self.cond(d - 1), e("int"), e("int"))
            if k < 0.93:
                return "%s[%s & 3]" % (r.choice(["ia", "ba", "sa", "ca"]), e("int"))
            return "main(%s)" % e("int")
        if t == "long":
            if k < 0.45:
                op = r.choice(["+", "-", "*", "&", "|", "^", "/", "%"])
                if op in ("/", "%"):
                    return "(%s %s (%s | 1L))" % (e("long"), op, e("long"))
                return "(%s %s %s)" % (e("long"), op, e("long"))
            if k < 0.55:
                return "(%s %s %s)" % (e("long"), r.choice(["<<", ">>", ">>>"]), e("int"))
            if k < 0.62:
                return "(- %s)" % e("long")
            if k < 0.75:
                return "((long) %s)" % ("(" + e(r.choice(["int", "double"])) + ")")
            if k < 0.85:
                return "(%s ? %s : %s)" % (self.cond(d - 1), e("long"), e("long"))
            if k < 0.92:
                return "la[%s & 3]" % e("int")
            return "main(%s)" % e("long")
        # double
        if k < 0.5:
            return "(%s %s %s)" % (e("double"), r.choice(["+", "-", "*", "/", "%"]), e("double"))
        if k < 0.58:
            return "(- %s)" % e("double")
        if k < 0.72:
            return "((double) %s)" % ("(" + e(r.choice(["int", "long"])) + ")")
        if k < 0.82:
            return "(%s ? %s : %s)" % (self.cond(d - 1), e("double"), e("double"))
        if k < 0.9:
            return "da[%s & 3]" % e("int")
        return "main(%s)" % e("double")

    def cond(self, d):
        t = self.r.choice(["int", "long", "double"])
        return "(%s %s %s)" % (self.expr(t, d), self.r.choice(["<", "<=", ">", ">=", "==", "!="]), self.expr(t, d))

    def fresh(self, prefix):
        self.names += 1
        return "%s%d" % (prefix, self.names)

    def statements(self, n, depth=0):
        r = self.r
        out = []
        ind = "        " + "    " * depth
        for s in range(n):
            k = r.random()
            lt = r.choice(["int", "long", "double"])
            if k < 0.35:
                name = self.fresh({"int": "x", "long": "y", "double": "z"}[lt])
                out.append("%s%s %s = %s;" % (ind, lt, name, self.expr(lt, 3)))
                self.scope.append((lt, name))
            elif k < 0.55:
                arr, cast = r.choice({"int": [("ia", "%s"), ("ba", "(byte) (%s)"), ("sa", "(short) (%s)"),
                                              ("ca", "(char) (0x7f & (%s))")],
                                      "long": [("la", "%s")], "double": [("da", "%s")]}[lt])
                out.append("%s%s[%s & 3] = %s;" % (ind, arr, self.expr("int", 1), cast % self.expr(lt, 3)))
            elif k < 0.65:
                f, cast = r.choice({"int": [("i", "%s"), ("b", "(byte) (%s)"), ("s", "(short) (%s)"),
                                            ("c", "(char) (0x7f & (%s))")],
                                    "long": [("l", "%s")], "double": [("d", "%s")]}[lt])
                out.append("%so.%s = %s;" % (ind, f, cast % self.expr(lt, 3)))
            elif k < 0.8 and depth == 0:
                acc = self.fresh({"int": "x", "long": "y", "double": "z"}[lt])
                i = self.fresh("i")
                out.append("%s%s %s = %s;" % (ind, lt, acc, self.expr(lt, 1)))
                out.append("%sfor (int %s = 0; %s < %d; %s++) {" % (ind, i, i, r.randint(1, 12), i))
                self.scope.append(("int", i))
                op = r.choice(["+", "-", "*", "^"]) if lt != "double" else r.choice(["+", "-", "*"])
                out.append("%s    %s = %s %s %s;" % (ind, acc, acc, op, self.expr(lt, 2)))
                self.scope.remove(("int", i))
                out.append("%s}" % ind)
                self.scope.append((lt, acc))
            elif depth == 0:
                x = self.fresh({"int": "x", "long": "y", "double": "z"}[lt])
                out.append("%s%s %s;" % (ind, lt, x))
                cases = sorted(set(r.choice([-1000, -3, -1, 0, 1, 2, 3, 5, 7, 100, 65536]) for _ in range(r.randint(1, 4))))
                out.append("%sswitch ((int) (%s)) {" % (ind, self.expr("int", 2)))
                for c in cases:
                    out.append("%scase %d:" % (ind, c))
                    out.append("%s    %s = %s;" % (ind, x, self.expr(lt, 2)))
                    out.append("%s    break;" % ind)
                out.append("%sdefault:" % ind)
                out.append("%s    %s = %s;" % (ind, x, self.expr(lt, 2)))
                out.append("%s}" % ind)
                self.scope.append((lt, x))
        return out

    def helper(self, k):
        t = self.r.choice(["int", "long", "double"])
        name = "h%d" % k
        self.scope = [("int", "p"), ("long", "q"), ("double", "w")]
        body = self.statements(self.r.randint(0, 2))
        ret = self.expr(t, 3)
        self.scope = []
        self.helpers.append((t, name))
        return "    static %s %s(int p, long q, double w) {\n%s\n        return %s;\n    }\n" % (
            t, name, "\n".join(body), ret)

    def gate(self, k, t):
        """A synchronized method of lk returning a branch's result, which the branch leaves on the
        operand stack: with one or two int parameters, the result lies where the monitor exit's
        frames or its unlock's locals are (patch 23)."""
        name = "s%d" % k
        n = self.r.randint(1, 2)
        self.scope = [("int", "p"), ("int", "p2")][:n]
        if t == "boolean":
            ret = self.cond(2)
        else:
            ret = "%s ? %s : %s" % (self.cond(2), self.expr(t, 2), self.expr(t, 2))
        self.scope = []
        self.gates.append((t, name, n))
        return "        synchronized %s %s(%s) {\n            return %s;\n        }\n" % (
            t, name, ", ".join("int " + p for p in ("p", "p2")[:n]), ret)

    def method(self, k):
        t = self.r.choice(["int", "long", "double"])
        self.scope = []
        body = self.statements(self.r.randint(0, 4))
        v = self.expr(t, 4)
        self.scope = []
        if t == "int":
            ret = "(long) (%s)" % v
        elif t == "long":
            ret = "%s" % v
        else:
            ret = "Double.doubleToRawLongBits(%s)" % v
        return "    static long v%d() {\n%s\n        return %s;\n    }\n" % (k, "\n".join(body), ret)


def main():
    seed, count, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    expected = None
    if len(sys.argv) > 4:
        expected = [int(line) for line in open(sys.argv[4]) if line.strip()]
    g = Gen(seed)
    cls = "G%d" % seed
    helpers = [g.helper(k) for k in range(max(2, count // 10))]
    gates = [g.gate(k, t) for k, t in enumerate(["boolean", "int", "long", "double"])]
    methods = [g.method(k) for k in range(count)]
    src = ["package difftest;\n", "import vm.VMTest;\n",
           "/** Generated by hvm/difftest/gen.py %d %d: do not edit. */" % (seed, count),
           "public class %s {" % cls]
    for t, name, init in g.fields:
        src.append("    static %s %s = %s;" % (t, name, init))
    for a in ("int ia", "long la", "double da", "byte ba", "short sa", "char ca"):
        t, n = a.split()
        src.append("    static %s[] %s = new %s[4];" % (t, n, t))
    src.append("""
    static final class O {
        int i = 0x7ffffff0;
        long l = -0x123456789L;
        double d = -0.0;
        byte b = (byte) -100;
        short s = (short) -30000;
        char c = (char) 100;
    }

    static O o = new O();""")
    src.append("""
    /** The gates: synchronized methods returning a branch's result (lk's monitor, Gates.install). */
    static final class L {
%s    }

    static L lk = new L();

    /**
     * On the HVM only (main): lk gets a monitor whose unlock handles a float, so it stays
     * interpreted (patch 18) and keeps its locals on the stack the monitor exit gives it, as the
     * SCJ monitor's unlock writes there. A scheduler is set for the VM to include the monitor
     * exit's Java code; it gives later objects of L the same kind of monitor.
     */
    static final class Gates {
        static void install() {
            vm.Machine.setCurrentScheduler(new OneThread());
            new Scribbling().attach(lk);
        }
    }

    static final class Scribbling extends vm.Monitor {
        static int exits;

        public void lock() {
        }

        public void unlock() {
            int w1 = -1, w2 = -1, w3 = -1, w4 = -1, w5 = -1, w6 = -1;
            float weight = 1f;
            exits += (w1 & w2 & w3 & w4 & w5 & w6) == -1 && weight == 1f ? 1 : 0;
        }
    }

    static final class OneThread implements vm.Scheduler {
        public vm.Process getNextProcess() {
            return null;
        }

        public void wait(Object target) {
        }

        public void notify(Object target) {
        }

        public void notifyAll(Object target) {
        }

        public vm.Monitor getDefaultMonitor() {
            return new Scribbling();
        }

        public void terminated() {
        }
    }""" % "".join(gates))
    src.append("""
    // icecap -aot compiles every method except those named main: these stay interpreted, and the
    // compiled v methods call them (ints, longs and doubles crossing both ways).
    static int main(int x) {
        return x;
    }

    static long main(long x) {
        return x;
    }

    static double main(double x) {
        return x;
    }
""")
    src.extend(helpers)
    src.extend(methods)
    if expected is None:
        src.append("    public static void main(String[] args) {\n    }\n}\n")
    else:
        assert len(expected) == count
        src.append("    static final long[] EXPECTED = {")
        for k in range(0, count, 4):
            src.append("        " + " ".join("%dL," % v for v in expected[k:k + 4]))
        src.append("    };\n")
        src.append("""    static boolean isNaN(long bits) {
        return (bits & 0x7ff0000000000000L) == 0x7ff0000000000000L && (bits & 0xfffffffffffffL) != 0;
    }

    static long value(int k) {
        switch (k) {""")
        for k in range(count):
            src.append("        case %d: return v%d();" % (k, k))
        src.append("""        default: return 0;
        }
    }

    // main is interpreted (icecap -aot never compiles main); the v methods and value are compiled.
    public static void main(String[] args) {
        Gates.install();
        int bad = 0;
        for (int k = 0; k < EXPECTED.length; k++) {
            long got = value(k);
            if (got != EXPECTED[k] && !(isNaN(got) && isNaN(EXPECTED[k]))) {
                devices.Console.println(k);
                bad++;
            }
        }
        VMTest.markResult(bad != 0);
    }
}
""")
    with open(out, "w") as f:
        f.write("\n".join(src))


if __name__ == "__main__":
    main()
