package org.jmclbench.workload;

import java.util.Locale;

import org.jmclbench.core.mcl.MclConfig;
import org.jmclbench.workload.engine.Engine;
import org.jmclbench.workload.engine.Engines;
import org.jmclbench.workload.rtsj.RtsjDesign;
import org.jmclbench.core.policy.OverrunPolicy;

/**
 * Parses the workload's command line (docs/FORMATS.md section 2): the thesis's short flags
 * ({@code -p -n -j -O -odo -laser -real -T -c -h}) and the long options, as
 * {@code --name value} or {@code --name=value}. Any problem is a {@link BadInputException}
 * naming the option.
 */
public final class RunOptionsParser {
    /** The usage text, one line an option with its default. */
    public static final String USAGE = String.join("\n",
            "usage: jmclbench run [options]",
            "  -p, --particles N        particle count (default 400)",
            "  -n, --number N           number of the test, the last folder of the run path (default 1)",
            "  -j, --runtime-name NAME  runtime name in the output path (default: <java.vendor>-<java version>)",
            "  -O, --out DIR            output root (default results)",
            "  -odo F -laser F -real F  thesis-format data files (all three together)",
            "  --dataset DIR            dataset folder (default data/match-short under the project home)",
            "  -T                       same as --policy terminate",
            "  --policy " + policyLabels() + "   event released while a job runs (default skip)",
            "  --ideal                  one thread, no timing: the infinitely fast computer",
            "  -c, --covariance         compute and write the covariance after each update",
            "  --engine javase|scj|rtsj|hvm  the Java SE release engine, the SCJ mission, the thesis's RTSJ",
            "                           program, or the SCJ mission on the icecap HVM (docs/HVM.md; same as",
            "                           jmclbench run-hvm) (default javase)",
            "  --rtsj-design thesis|atomic  rtsj: terminate's ATC deferred by the robot's monitor (thesis), or",
            "                           delivered at the job's polls before its commit (atomic) (default thesis)",
            "  --memory STYLE           memory style: preallocated|allocating (javase, rtsj), preallocated|scoped",
            "                           (scj, hvm); default preallocated",
            "  --area-size AREA=BYTES   scj, hvm: size of a memory area (immortal, mission, predict, update, sensor);",
            "                           repeatable (default: computed from particles and events)",
            "  --estimate mean|best     estimate (default mean)",
            "  --resample systematic|multinomial  resampling (default systematic)",
            "  --init known|uniform     initialisation (default known)",
            "  --seed N                 random generator seed (default 1)",
            "  --time-scale F           multiplies event times and deadlines; 0.5 = twice as fast (1e-6 to 1000, default 1.0)",
            "  --warmup S               replay the first S seconds of data first and discard them (default 0)",
            "  --spin-us N              park until N us before each release, then spin (default 0)",
            "  --gc-log                 keep the runtime's GC log as gc.log in the run folder",
            "  --no-cpu-time            javase, rtsj, ideal: no per-job CPU time (cpu_ns -1), two clock reads per job fewer",
            "  --load-alloc MBPS,LIVEMB background allocation load: MB/s allocated, MB kept live (default off)",
            "  --load-name NAME         load scenario recorded with the run (default alloc with --load-alloc, else none)",
            "  --force                  overwrite a complete run folder",
            "  -h, --help               this help");

    private RunOptionsParser() {
    }

    /** Parses args; a leading {@code run} is accepted and ignored. */
    public static RunOptions parse(String[] args) throws BadInputException {
        RunOptions o = new RunOptions();
        Line line = new Line(args, args.length > 0 && "run".equals(args[0]) ? 1 : 0);
        boolean terminateFlag = false;
        boolean policyGiven = false;
        boolean designGiven = false;
        while (line.hasNext()) {
            String name = line.option();
            switch (name) {
                case "-h":
                case "--help":
                    line.noValue(name);
                    o.help = true;
                    break;
                case "-p":
                case "--particles":
                    o.particles = intIn(name, line.value(name), 1, 100_000_000);
                    break;
                case "-n":
                case "--number":
                    o.number = intIn(name, line.value(name), 0, Integer.MAX_VALUE);
                    break;
                case "-j":
                case "--runtime-name":
                    o.runtimeName = pathComponent(name, line.value(name));
                    break;
                case "-O":
                case "--out":
                    o.out = nonEmpty(name, line.value(name));
                    break;
                case "-odo":
                case "--odo":
                    o.odo = nonEmpty(name, line.value(name));
                    break;
                case "-laser":
                case "--laser":
                    o.laser = nonEmpty(name, line.value(name));
                    break;
                case "-real":
                case "--real":
                    o.real = nonEmpty(name, line.value(name));
                    break;
                case "--dataset":
                    o.dataset = nonEmpty(name, line.value(name));
                    break;
                case "-T":
                    terminateFlag = true;
                    break;
                case "--policy":
                    o.policy = policy(name, line.value(name));
                    policyGiven = true;
                    break;
                case "--ideal":
                    line.noValue(name);
                    o.ideal = true;
                    break;
                case "-c":
                case "--covariance":
                    line.noValue(name);
                    o.covariance = true;
                    break;
                case "--memory":
                    o.memory = choice(name, line.value(name), MclConfig.Memory.class);
                    break;
                case "--engine":
                    o.engine = Engines.named(name, line.value(name)).name();
                    break;
                case "--rtsj-design": {
                    String v = line.value(name);
                    o.rtsjDesign = RtsjDesign.of(v);
                    if (o.rtsjDesign == null) {
                        throw BadInputException.ofOption(name, "'" + v + "' is not one of thesis|atomic");
                    }
                    designGiven = true;
                    break;
                }
                case "--area-size": {
                    String v = line.value(name);
                    int eq = v.indexOf('=');
                    if (eq <= 0) {
                        throw BadInputException.ofOption(name, "'" + v + "' must be AREA=BYTES (e.g. mission=200000)");
                    }
                    String area = v.substring(0, eq);
                    String[] areas = missionAreas();
                    if (!java.util.Arrays.asList(areas).contains(area)) {
                        throw BadInputException.ofOption(name, "'" + area + "' is not an area of the mission ("
                                + String.join(", ", areas) + ")");
                    }
                    o.areaSizes.put(area, (long) intIn(name, v.substring(eq + 1), 1, Integer.MAX_VALUE));
                    break;
                }
                case "--estimate":
                    o.estimate = choice(name, line.value(name), MclConfig.Estimate.class);
                    break;
                case "--resample":
                    o.resample = choice(name, line.value(name), MclConfig.Resample.class);
                    break;
                case "--init":
                    o.init = choice(name, line.value(name), MclConfig.Init.class);
                    break;
                case "--seed":
                    o.seed = longValue(name, line.value(name));
                    break;
                case "--time-scale":
                    o.timeScale = timeScale(name, line.value(name));
                    break;
                case "--warmup":
                    o.warmupS = doubleIn(name, line.value(name), true);
                    break;
                case "--spin-us":
                    o.spinUs = intIn(name, line.value(name), 0, 1_000_000);
                    break;
                case "--gc-log":
                    line.noValue(name);
                    o.gcLog = true;
                    break;
                case "--no-cpu-time":
                    line.noValue(name);
                    o.cpuTime = false;
                    break;
                case "--load-alloc": {
                    String v = line.value(name);
                    String[] parts = v.split(",", -1);
                    if (parts.length != 2) {
                        throw BadInputException.ofOption(name, "'" + v + "' must be MBPS,LIVEMB (e.g. 200,32)");
                    }
                    o.loadAllocMbPerS = intIn(name, parts[0], 1, 100_000);
                    o.loadAllocLiveMb = intIn(name, parts[1], 0, 1_000_000);
                    break;
                }
                case "--load-name":
                    o.loadName = pathComponent(name, line.value(name));
                    break;
                case "--force":
                    line.noValue(name);
                    o.force = true;
                    break;
                default:
                    if (name.startsWith("-")) {
                        throw BadInputException.ofOption(name, "unknown option (see --help)");
                    }
                    throw BadInputException.ofOption(name, "unexpected argument (see --help)");
            }
        }
        if (o.help) {
            return o; // help is shown whatever else the line holds (the C baseline's rule too)
        }
        if (terminateFlag) {
            if (policyGiven && o.policy != OverrunPolicy.TERMINATE) {
                throw BadInputException.ofOption("-T", "contradicts --policy " + o.policy.label);
            }
            o.policy = OverrunPolicy.TERMINATE;
        }
        int files = (o.odo != null ? 1 : 0) + (o.laser != null ? 1 : 0) + (o.real != null ? 1 : 0);
        if (files != 0 && files != 3) {
            String missing = o.odo == null ? "-odo" : o.laser == null ? "-laser" : "-real";
            throw BadInputException.ofOption(missing, "missing: -odo, -laser and -real go together");
        }
        if (files == 3 && o.dataset != null) {
            throw BadInputException.ofOption("--dataset", "cannot be combined with -odo/-laser/-real");
        }
        if (designGiven && !"rtsj".equals(o.engine)) {
            throw BadInputException.ofOption("--rtsj-design", "chooses the rtsj engine's design: needs --engine rtsj");
        }
        if (o.ideal) {
            Engines.of(o).checkOptions(o); // what the ideal run cannot apply, before the engine's own checks
        }
        Engine engine = Engines.named("--engine", o.engine);
        engine.checkOptions(o);
        o.engineRuntimeName = engine.runtimeName(RunOptions.defaultRuntimeName(), o);
        return o;
    }

    private static OverrunPolicy policy(String name, String v) throws BadInputException {
        OverrunPolicy p = OverrunPolicy.ofLabel(v);
        if (p == null) {
            throw BadInputException.ofOption(name, "'" + v + "' is not one of " + policyLabels());
        }
        return p;
    }

    /** The {@code --policy} values in code order, {@code skip|terminate|queue}: the usage's and the errors' one list. */
    public static String policyLabels() {
        StringBuilder allowed = new StringBuilder();
        for (OverrunPolicy each : OverrunPolicy.values()) {
            allowed.append(allowed.length() == 0 ? "" : "|").append(each.label);
        }
        return allowed.toString();
    }

    /** The command line as it is read: the arguments, the next one's index and the current option's inline value. */
    private static final class Line {
        private final String[] args;
        private int next;
        private String inline;

        Line(String[] args, int first) {
            this.args = args;
            this.next = first;
        }

        boolean hasNext() {
            return next < args.length;
        }

        /** Reads the next argument: an option's name; the value of a {@code --name=value} is kept for {@link #value}. */
        String option() {
            String arg = args[next++];
            inline = null;
            if (arg.startsWith("--")) {
                int eq = arg.indexOf('=');
                if (eq > 0) {
                    inline = arg.substring(eq + 1);
                    return arg.substring(0, eq);
                }
            }
            return arg;
        }

        /** The current option's value: the one given with {@code =}, else the next argument, which it consumes. */
        String value(String name) throws BadInputException {
            if (inline != null) {
                return inline;
            }
            if (next >= args.length) {
                throw BadInputException.ofOption(name, "needs a value");
            }
            return args[next++];
        }

        void noValue(String name) throws BadInputException {
            if (inline != null) {
                throw BadInputException.ofOption(name, "takes no value");
            }
        }
    }

    private static String nonEmpty(String name, String v) throws BadInputException {
        if (v.isEmpty()) {
            throw BadInputException.ofOption(name, "must not be empty");
        }
        return v;
    }

    /** The longest folder name the file systems we run on take (NAME_MAX), as the C baseline checks it. */
    private static final int FOLDER_NAME_MAX = 255;

    /** A name used as a folder of the run path: letters, digits and . _ + - only, so it cannot escape the output root. */
    private static String pathComponent(String name, String v) throws BadInputException {
        if (!v.matches("[A-Za-z0-9._+-]+") || v.equals(".") || v.equals("..")) {
            throw BadInputException.ofOption(name, "'" + v + "' must be letters, digits, '.', '_', '+' or '-'");
        }
        // a longer one would fail only when the run folder is made, blamed on -O
        if (v.length() > FOLDER_NAME_MAX) {
            throw BadInputException.ofOption(name, v.length() + " characters, longer than a folder name may be ("
                    + FOLDER_NAME_MAX + ")");
        }
        return v;
    }

    /** An integer: {@code [+-]?[0-9]+}, nothing else (Long.parseLong takes other scripts' digits; C does not). */
    private static final java.util.regex.Pattern INTEGER = java.util.regex.Pattern.compile("[+-]?[0-9]+");
    /** A number: the data files' grammar (docs/FORMATS.md 1.1), the C baseline's too. */
    private static final java.util.regex.Pattern DECIMAL =
            java.util.regex.Pattern.compile("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?");

    private static int intIn(String name, String v, int min, int max) throws BadInputException {
        long x;
        try {
            x = longOf(v);
        } catch (NumberFormatException e) {
            throw BadInputException.ofOption(name, "not an integer: '" + v + "'");
        }
        if (x < min || x > max) {
            throw BadInputException.ofOption(name, x + " is out of range [" + min + ", " + max + "]");
        }
        return (int) x;
    }

    private static long longOf(String v) {
        if (!INTEGER.matcher(v).matches()) {
            throw new NumberFormatException(v);
        }
        return Long.parseLong(v);
    }

    private static long longValue(String name, String v) throws BadInputException {
        try {
            return longOf(v);
        } catch (NumberFormatException e) {
            throw BadInputException.ofOption(name, "not an integer: '" + v + "'");
        }
    }

    private static double timeScale(String name, String v) throws BadInputException {
        double x = doubleIn(name, v, false);
        if (x < RunOptions.TIME_SCALE_MIN || x > RunOptions.TIME_SCALE_MAX) {
            throw BadInputException.ofOption(name, "'" + v + "' is out of range [1e-6, 1000]");
        }
        return x;
    }

    private static double doubleIn(String name, String v, boolean zeroAllowed) throws BadInputException {
        if (!DECIMAL.matcher(v).matches()) {
            throw BadInputException.ofOption(name, "not a number: '" + v + "'");
        }
        double x = Double.parseDouble(v);
        if (Double.isNaN(x) || Double.isInfinite(x) || x < 0 || (!zeroAllowed && x == 0)) {
            throw BadInputException.ofOption(name, "'" + v + "' must be a finite number "
                    + (zeroAllowed ? ">= 0" : "> 0"));
        }
        return x;
    }

    private static <E extends Enum<E>> E choice(String name, String v, Class<E> type) throws BadInputException {
        StringBuilder allowed = new StringBuilder();
        for (E e : type.getEnumConstants()) {
            String label = e.name().toLowerCase(Locale.ROOT);
            if (label.equals(v)) {
                return e;
            }
            if (allowed.length() > 0) {
                allowed.append('|');
            }
            allowed.append(label);
        }
        throw BadInputException.ofOption(name, "'" + v + "' is not one of " + allowed);
    }

    /**
     * The SCJ mission's area names (scj-mission's {@code MissionSizes}), by name: the rtsj engine's
     * build for an RTSJ VM ({@code ant rtsj-engine}) has no SCJ variant, and no area then.
     */
    private static String[] missionAreas() {
        try {
            return (String[]) Class.forName("org.jmclbench.scj.MissionSizes").getField("AREA_NAMES").get(null);
        } catch (ReflectiveOperationException | LinkageError e) {
            return new String[0];
        }
    }
}
