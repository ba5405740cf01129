package org.jmclbench.tooling.cli;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.Reader;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The lines of a text file a runtime under test wrote (job lines, data files, a GC log), one at a
 * time, each of at most {@link #MAX_LINE_CHARS} characters: a runaway file of gigabytes, or one
 * without a line end, read whole or as one line would take the harness's memory with it. Lines end
 * with LF, CR or CRLF (as {@code BufferedReader.readLine} reads them); bytes that are not UTF-8
 * read as U+FFFD, so that a damaged line is refused where it is parsed, naming file:line.
 */
public final class BoundedLineReader implements Closeable {
    /** The longest line read by default (a job line is under 200 characters, a GC log line under 1,000). */
    public static final int MAX_LINE_CHARS = 64 * 1024;

    private final Path file;
    private final int maxLineChars;
    private final Reader in;
    private final char[] buf = new char[8192];
    private final StringBuilder line = new StringBuilder();
    private int pos;
    private int len;
    private boolean afterCr;
    private int lineNumber;

    /** Reads {@code file} with the default limit. */
    public BoundedLineReader(Path file) throws IOException {
        this(file, MAX_LINE_CHARS);
    }

    /** Reads {@code file}, refusing a line longer than {@code maxLineChars}. */
    public BoundedLineReader(Path file, int maxLineChars) throws IOException {
        this.file = file;
        this.maxLineChars = maxLineChars;
        this.in = new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPLACE).onUnmappableCharacter(CodingErrorAction.REPLACE));
    }

    /**
     * The next line without its end, or null after the last.
     *
     * @throws IOException {@code file:line: a line longer than N characters} for a line past the limit
     */
    public String readLine() throws IOException {
        line.setLength(0);
        while (true) {
            if (pos == len) {
                len = in.read(buf);
                pos = 0;
                if (len <= 0) {
                    len = 0;
                    if (line.length() == 0) {
                        return null;
                    }
                    lineNumber++;
                    return line.toString();
                }
            }
            char c = buf[pos++];
            if (c == '\n' && afterCr) {
                afterCr = false;
                continue;
            }
            afterCr = c == '\r';
            if (c == '\n' || c == '\r') {
                lineNumber++;
                return line.toString();
            }
            if (line.length() == maxLineChars) {
                throw new IOException(file + ":" + (lineNumber + 1) + ": a line longer than " + maxLineChars + " characters");
            }
            line.append(c);
        }
    }

    /** The number of the line {@link #readLine} returned last (1 for the first). */
    public int lineNumber() {
        return lineNumber;
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
