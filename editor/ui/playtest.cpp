#include "ui/playtest.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <string_view>
#include <sys/wait.h>
#include <unistd.h>

namespace ks::editor::ui {

RuntimeOptions parse_runtime_help(const std::string& help_text) {
    RuntimeOptions o;
    o.screen = help_text.find("--screen") != std::string::npos;
    o.warp = help_text.find("--warp") != std::string::npos;
    o.camera = help_text.find("--camera") != std::string::npos;
    o.logic_trace = help_text.find("--logic-trace") != std::string::npos;
    return o;
}

std::filesystem::path playtest_runtime(const std::filesystem::path& executable_dir) {
    if (const char* command = std::getenv("KS_PLAYTEST_COMMAND"); command && *command) return command;
    return executable_dir / "killswitch";
}

RuntimeOptions query_runtime_options(const std::filesystem::path& runtime) {
    std::string text;
    const std::string command = "'" + runtime.string() + "' --help 2>&1";
    if (FILE* pipe = popen(command.c_str(), "r")) {
        char buffer[1024];
        while (size_t n = std::fread(buffer, 1, sizeof(buffer), pipe)) text.append(buffer, n);
        pclose(pipe);
    }
    return parse_runtime_help(text);
}

std::vector<std::string> playtest_arguments(const std::filesystem::path& level,
                                            const std::optional<PlayStart>& start,
                                            const RuntimeOptions& runtime) {
    std::vector<std::string> args = {"--level", level.string()};
    if (runtime.screen) args.insert(args.end(), {"--screen", "play"});
    if (runtime.logic_trace) args.insert(args.end(), {"--logic-trace", "-"});
    if (start) {
        char text[128];
        if (runtime.warp || !runtime.camera) {
            std::snprintf(text, sizeof(text), "%.3f,%.3f,%.3f,%.1f,0", start->position.x, start->position.y,
                          start->position.z, start->yaw_degrees);
            args.insert(args.end(), {"--warp", text});
        } else { // the eye three units above the feet (the reference's eye height)
            std::snprintf(text, sizeof(text), "%.3f,%.3f,%.3f,%.1f,0", start->position.x,
                          start->position.y + 3.0f, start->position.z, start->yaw_degrees);
            args.insert(args.end(), {"--camera", text});
        }
    }
    return args;
}

PlayTest::~PlayTest() {
    if (pipe_ >= 0) close(pipe_);
    // The game window stays open when the editor quits; it is the user's to close, so it is not killed,
    // only no longer reaped by us.
}

Result<void> PlayTest::start(const std::filesystem::path& runtime, const std::vector<std::string>& arguments,
                             const std::vector<std::pair<std::string, std::string>>& environment) {
    if (running()) return Error{"a play-test is already running", {}, "close the game window first"};
    std::error_code ec;
    if (!std::filesystem::exists(runtime, ec))
        return Error{"the runtime is missing: " + runtime.string(),
                     {},
                     "build the 'killswitch' target; the editor looks for it next to itself"};
    int fds[2];
    if (pipe(fds) != 0) return Error{std::string("pipe failed: ") + std::strerror(errno), {}, ""};
    std::vector<std::string> argv_text = {runtime.string()};
    argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (auto& a : argv_text) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The child's environment is made here: between fork and exec only async-signal-safe calls are allowed.
    std::vector<std::string> env_text;
    for (char** e = environ; *e; ++e) {
        const std::string_view entry(*e);
        bool replaced = false;
        for (const auto& [name, value] : environment) replaced |= entry.starts_with(name + "=");
        if (!replaced) env_text.emplace_back(entry);
    }
    for (const auto& [name, value] : environment) env_text.push_back(name + "=" + value);
    std::vector<char*> envp;
    for (auto& e : env_text) envp.push_back(e.data());
    envp.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return Error{std::string("fork failed: ") + std::strerror(errno), {}, ""};
    }
    if (pid == 0) {
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        execve(argv[0], argv.data(), envp.data());
        std::fprintf(stderr, "could not start %s: %s\n", argv[0], std::strerror(errno));
        _exit(127);
    }
    close(fds[1]);
    fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
    pid_ = pid;
    pipe_ = fds[0];
    partial_.clear();
    exit_code_.reset();
    return {};
}

void PlayTest::poll(std::vector<std::string>& lines) {
    if (pipe_ >= 0) {
        char buffer[4096];
        for (;;) {
            const ssize_t n = read(pipe_, buffer, sizeof(buffer));
            if (n <= 0) {
                if (n == 0) { // writer closed: the child is ending
                    close(pipe_);
                    pipe_ = -1;
                }
                break;
            }
            partial_.append(buffer, static_cast<size_t>(n));
            for (size_t nl; (nl = partial_.find('\n')) != std::string::npos;) {
                lines.push_back(partial_.substr(0, nl));
                partial_.erase(0, nl + 1);
            }
        }
    }
    if (pid_ > 0) {
        int status = 0;
        if (waitpid(pid_, &status, WNOHANG) == pid_) {
            if (!partial_.empty()) lines.push_back(partial_), partial_.clear();
            exit_code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            pid_ = -1;
        }
    }
}

void PlayTest::stop() {
    if (pid_ > 0) kill(pid_, SIGTERM);
}

} // namespace ks::editor::ui
