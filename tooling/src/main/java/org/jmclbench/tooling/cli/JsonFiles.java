package org.jmclbench.tooling.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * JSON files a command is given (a run's summary.json, verify's results): read whole, and one that is
 * not JSON, or not the object it must be, is bad input in one line naming the file and line (Jackson's
 * own message spans lines: the source and location follow the problem).
 */
public final class JsonFiles {

    private JsonFiles() {
    }

    /**
     * The JSON object in {@code file}.
     *
     * @param option the option that named the file, for the message; null when it was found, not named
     * @throws BadUsageException {@code [option: ]file[:line]: problem} when the file cannot be read, is not
     *                           JSON or holds no object (an empty file holds none)
     */
    public static JsonNode readObject(Path file, String option) {
        String where = (option == null ? "" : option + ": ") + file;
        JsonNode doc;
        try {
            doc = new ObjectMapper().readTree(file.toFile());
        } catch (JsonProcessingException e) {
            JsonLocation at = e.getLocation();
            throw new BadUsageException(where + (at != null && at.getLineNr() > 0 ? ":" + at.getLineNr() : "") + ": not JSON ("
                    + oneLine(e.getOriginalMessage()) + ")");
        } catch (IOException e) {
            throw new BadUsageException(where + ": cannot read (" + (Files.exists(file) ? oneLine(e.getMessage()) : "no such file") + ")");
        }
        if (doc == null || !doc.isObject()) {
            throw new BadUsageException(where + ": not a JSON object");
        }
        return doc;
    }

    private static String oneLine(String s) {
        return String.valueOf(s).replaceAll("\\s+", " ").strip();
    }
}
