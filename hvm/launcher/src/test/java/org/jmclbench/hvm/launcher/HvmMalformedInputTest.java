package org.jmclbench.hvm.launcher;

import org.jmclbench.workload.MalformedInputCorpusTest;

/**
 * The malformed-input corpus with the hvm engine on the class path: every kind of bad dataset
 * is refused by the hvm path (which reads its data on the Java side, before anything is built)
 * exactly as by the javase and scj engines and the C baseline.
 */
class HvmMalformedInputTest extends MalformedInputCorpusTest {
}
