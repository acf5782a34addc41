#include "coal_peer.h"

#include "coal_wire.h"

#include <spawn.h>
#include <sys/wait.h>

#include <csignal>
#include <filesystem>
#include <stdexcept>

extern char** environ;

namespace prox::bench {

CoalPeer::CoalPeer(const std::string& executable) {
  // A peer that dies must be an error here, not a signal that ends the bench.
  std::signal(SIGPIPE, SIG_IGN);
  int to[2], from[2];
  if (::pipe(to) != 0) throw std::runtime_error("Coal peer: pipe failed");
  if (::pipe(from) != 0) {
    ::close(to[0]), ::close(to[1]);
    throw std::runtime_error("Coal peer: pipe failed");
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, to[0], 0);
  posix_spawn_file_actions_adddup2(&actions, from[1], 1);
  for (int fd : {to[0], to[1], from[0], from[1]}) posix_spawn_file_actions_addclose(&actions, fd);
  char* argv[] = {const_cast<char*>(executable.c_str()), nullptr};
  const int err = posix_spawn(&pid_, executable.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(to[0]), ::close(from[1]);
  to_ = to[1], from_ = from[0];
  if (err != 0) {
    pid_ = -1;
    ::close(to_), ::close(from_);
    to_ = from_ = -1;
    throw std::runtime_error("Coal peer: cannot start " + executable);
  }
}

CoalPeer::~CoalPeer() {
  if (to_ >= 0) ::close(to_);  // end of input ends the peer
  if (from_ >= 0) ::close(from_);
  if (pid_ > 0) ::waitpid(pid_, nullptr, 0);
}

void CoalPeer::fail(const char* what) {
  std::string message = std::string("Coal peer: ") + what;
  ::close(to_), ::close(from_);
  to_ = from_ = -1;
  int status = 0;
  if (pid_ > 0 && ::waitpid(pid_, &status, 0) == pid_) {
    if (WIFSIGNALED(status)) message += ", it died of signal " + std::to_string(WTERMSIG(status));
    if (WIFEXITED(status)) message += ", it exited with " + std::to_string(WEXITSTATUS(status));
  }
  pid_ = -1;
  throw std::runtime_error(message);
}

std::string CoalPeer::version() {
  std::uint32_t length = 0;
  std::string out;
  if (!wire::put(to_, 'V') || !wire::get(from_, length)) fail("no answer to 'version'");
  out.resize(length);
  if (!wire::read_all(from_, out.data(), length)) fail("no answer to 'version'");
  return out;
}

CoalBuild CoalPeer::build(const Mesh& mesh, int reps) {
  std::vector<double> xyz;
  xyz.reserve(3 * std::size_t(mesh.vertex_count()));
  for (std::uint32_t v = 0; v < mesh.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) xyz.push_back(mesh.vertex(v)[k]);
  std::vector<std::uint32_t> abc;
  abc.reserve(3 * std::size_t(mesh.triangle_count()));
  for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) abc.push_back(mesh.indices(t)[k]);
  const auto n = static_cast<std::uint32_t>(reps);
  if (!wire::put(to_, 'M') || !wire::put(to_, n) || !wire::put(to_, mesh.vertex_count()) ||
      !wire::put(to_, mesh.triangle_count()) || !wire::put_vector(to_, xyz) || !wire::put_vector(to_, abc))
    fail("cannot send a mesh");
  CoalBuild out;
  if (!wire::get(from_, out.mesh) || !wire::get_vector(from_, out.seconds, n)) fail("no answer to 'build'");
  return out;
}

CoalMargin CoalPeer::margin_collide(std::uint32_t a, std::uint32_t b, const Pose& pose_b, double margin) {
  double rotation[9], translation[3];
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row)
      rotation[3 * col + row] = pose_b.rotation[col][row];  // glm: column-major
  for (int k = 0; k < 3; ++k) translation[k] = pose_b.translation[k];
  if (!wire::put(to_, 'C') || !wire::put(to_, a) || !wire::put(to_, b) || !wire::put(to_, margin) ||
      !wire::put(to_, rotation) || !wire::put(to_, translation))
    fail("cannot send a collide request");
  CoalMargin out;
  std::uint64_t pairs = 0;
  if (!wire::get(from_, out.seconds) || !wire::get(from_, pairs) || !wire::get(from_, out.min_distance))
    fail("no answer to 'collide'");
  out.pairs = static_cast<std::size_t>(pairs);
  return out;
}

std::string coal_peer_beside_self() {
  return (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "proxima_coal_peer").string();
}

}  // namespace prox::bench
