/* Runs a program under test as a child process and reads back what it printed (test_e2e, test_tools). */
#ifndef JM_CHILD_H
#define JM_CHILD_H

#include <fcntl.h>
#include <stdio.h>
#include <sys/wait.h>
#include <unistd.h>

/* Reads up to len - 1 bytes of path into buf, NUL-terminated (empty when it cannot be read). */
static inline void jt_slurp(const char *path, char *buf, size_t len)
{
	FILE *f = fopen(path, "r");
	size_t n = 0;

	if (f) {
		n = fread(buf, 1, len - 1, f);
		fclose(f);
	}
	buf[n] = '\0';
}

/*
 * Runs argv (NULL-terminated, argv[0] a path) with its stdout and stderr in dir/stdout and
 * dir/stderr, read back into out and err; returns its exit status, -1 when it did not exit.
 */
static inline int jt_run_child(const char *const *argv, const char *dir, char *out, size_t out_len, char *err,
			       size_t err_len)
{
	char outp[128], errp[128];
	int status;
	pid_t pid;

	snprintf(outp, sizeof(outp), "%s/stdout", dir);
	snprintf(errp, sizeof(errp), "%s/stderr", dir);
	pid = fork();
	if (pid == 0) {
		int o = open(outp, O_WRONLY | O_CREAT | O_TRUNC, 0644);
		int e = open(errp, O_WRONLY | O_CREAT | O_TRUNC, 0644);

		if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0)
			_exit(127);
		execv(argv[0], (char *const *)argv);
		_exit(127);
	}
	if (pid < 0 || waitpid(pid, &status, 0) != pid)
		return -1;
	jt_slurp(outp, out, out_len);
	jt_slurp(errp, err, err_len);
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/* The number of newlines in s. */
static inline int jt_count_lines(const char *s)
{
	int n = 0;

	for (; *s; s++)
		n += *s == '\n';
	return n;
}

#endif
