package hvmtest;

import vm.VMTest;

/**
 * What every patch's test program shares: it runs its checks 0..count-1, prints the number of each
 * one that fails and marks the program failed unless all passed (exit status, vm.VMTest). The
 * checks are instance methods outside main, so icecap's -aot compiles them in compiled mode.
 */
abstract class PatchCases {
    /** Check {@code i} of the program: true when the VM got it right. */
    abstract boolean check(int i);

    /** Runs checks 0..count-1 and sets the program's result. */
    final void run(int count) {
        int failed = 0;
        for (int i = 0; i < count; i++) {
            if (!check(i)) {
                devices.Console.println(i);
                failed++;
            }
        }
        VMTest.markResult(failed != 0);
    }
}
