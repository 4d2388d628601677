#include "mpi_driver/io/read_in_child.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <new>

#include <sys/resource.h>
#include <sys/wait.h>

#include "engine/errors.hpp"
#include "engine/number_text.hpp"
#include "mpi_driver/config/input_file.hpp"

namespace blockfrag {
namespace {

// The child's answer: one byte of kind, then the text.
constexpr char answer_ok = 'O';
constexpr char answer_refused = 'R';
constexpr char answer_failed = 'F';

void send_answer(int fd, const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t wrote = ::write(fd, text.data() + done, text.size() - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return;  // the parent is gone: nobody to answer
    done += static_cast<std::size_t>(wrote);
  }
}

[[noreturn]] void answer_and_exit(int fd, const std::string& name, std::size_t memory_bytes,
                                  const std::function<std::string()>& read) {
  if (child_memory_limited) {
    const rlimit memory{memory_bytes, memory_bytes};
    ::setrlimit(RLIMIT_AS, &memory);
  }
  std::string answer;
  try {
    answer = answer_ok + read();
  } catch (const std::bad_alloc&) {
    answer = answer_refused + name + ": reading it takes more than " +
             std::to_string(memory_bytes) + " bytes of memory: a damaged file";
  } catch (const InvalidInput& error) {
    answer = answer_refused + std::string(error.what());
  } catch (const std::exception& error) {
    answer = answer_failed + std::string(error.what());
  }
  send_answer(fd, answer);
  ::close(fd);
  ::_exit(0);  // no atexit handlers, no flushing of the parent's buffers a second time
}

class Pipe {
 public:
  Pipe() {
    if (::pipe(ends_) != 0) throw Error(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  ~Pipe() {
    for (const int fd : ends_) {
      if (fd >= 0) ::close(fd);
    }
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  int read_end() const { return ends_[0]; }
  int write_end() const { return ends_[1]; }
  void close_write_end() {
    ::close(ends_[1]);
    ends_[1] = -1;
  }

 private:
  int ends_[2] = {-1, -1};
};

}  // namespace

std::string read_in_child(const std::string& file, std::chrono::milliseconds limit,
                          std::size_t memory_bytes, const std::function<std::string()>& read) {
  const std::string name = printable_excerpt(file, 200);
  Pipe pipe;
  const pid_t child = ::fork();
  if (child < 0)
    throw Error(std::string("cannot fork to read ") + file + ": " + std::strerror(errno));
  if (child == 0) {
    ::close(pipe.read_end());
    answer_and_exit(pipe.write_end(), name, memory_bytes, read);
  }
  pipe.close_write_end();
  const auto deadline = std::chrono::steady_clock::now() + limit;
  std::string answer;
  bool finished = false;
  while (!finished) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    pollfd ready{pipe.read_end(), POLLIN, 0};
    const int polled = left.count() > 0 ? ::poll(&ready, 1, static_cast<int>(left.count())) : 0;
    if (polled < 0 && errno == EINTR) continue;
    if (polled <= 0) {
      ::kill(child, SIGKILL);
      ::waitpid(child, nullptr, 0);
      throw InvalidInput(name + ": still not read after " +
                         format_number(std::chrono::duration<double>(limit).count()) +
                         " s: a damaged file (HDF5 does not finish reading it)");
    }
    char buffer[65536];
    const ssize_t got = ::read(pipe.read_end(), buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      finished = true;
    } else {
      answer.append(buffer, static_cast<std::size_t>(got));
    }
  }
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || answer.empty()) {
    const std::string how = WIFSIGNALED(status)
                                ? std::string(strsignal(WTERMSIG(status)))
                                : "exit code " + std::to_string(WEXITSTATUS(status));
    throw InvalidInput(name + ": reading it crashed HDF5 (" + how + "): a damaged file");
  }
  const std::string text = answer.substr(1);
  if (answer.front() == answer_refused) throw InvalidInput(text);
  if (answer.front() == answer_failed) throw Error(text);
  return text;
}

}  // namespace blockfrag
