#pragma once
// Runs part of a test in a forked child process under a resource limit (its address space, the
// size of the files it writes), the way exhausted memory or a full disk would limit it: the limit
// binds only the child, and a crash shows as the signal that ended it rather than ending the test.
#include <cstdio>
#include <functional>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

// AddressSanitizer reserves terabytes of address space for its shadow, so an address-space limit
// cannot be set under it.
#if defined(__SANITIZE_ADDRESS__)
#define PTVIEW_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PTVIEW_UNDER_ASAN 1
#endif
#endif

namespace ptview::testing {

// The child's exit code when it could not set the limit.
constexpr int kLimitNotSet = 3;

struct ChildExit {
    int code = -1;  // the exit code when the child exited (-1 when it could not be started or waited for)
    int signal = 0; // the signal that ended it, if one did
};

// The address space this process uses now, in bytes (0 when /proc does not say): a limit set a
// little above it leaves only that little to allocate.
inline rlim_t addressSpaceInUse() {
    long pages = 0;
    if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%ld", &pages) != 1) pages = 0;
        std::fclose(statm);
    }
    return pages > 0 ? rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) : 0;
}

// Runs body in a child process with `resource` (RLIMIT_AS, RLIMIT_FSIZE, ...) limited to `bytes`;
// body's result is the child's exit code. body must not use gtest's assertions: they would be
// reported in the child, which the test does not see.
inline ChildExit runInLimitedChild(decltype(RLIMIT_AS) resource, rlim_t bytes, const std::function<int()>& body) {
    std::fflush(nullptr); // or the child would write the parent's buffered output a second time
    const pid_t child = ::fork();
    if (child < 0) return {};
    if (child == 0) {
        const rlimit limit{bytes, bytes};
        if (::setrlimit(resource, &limit) != 0) ::_exit(kLimitNotSet);
        ::_exit(body());
    }
    int status = 0;
    if (::waitpid(child, &status, 0) != child) return {};
    if (WIFSIGNALED(status)) return {-1, WTERMSIG(status)};
    return {WEXITSTATUS(status), 0};
}

} // namespace ptview::testing
