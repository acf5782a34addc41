# Sourced by the other scripts: installs missing Debian packages. Runs
# apt-get only when something is missing, so repeated runs are quick.
need_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "Installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# The compiler, CMake and the libraries the core and its tests need.
CORE_PACKAGES=(g++ cmake ninja-build libglm-dev libgtest-dev
  libtinygltf-dev nlohmann-json3-dev)  # glTF loading (PROX_WITH_GLTF)

# The scene benchmark's peers and plots (scripts/bench.sh): FCL to measure
# against (never a dependency of the SDK) and a venv for matplotlib.
BENCH_PACKAGES=(libbenchmark-dev libfcl-dev python3 python3-venv)
