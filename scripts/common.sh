# Shared by the scripts: Debian packages the build needs, installed when missing (as root).
# shellcheck shell=bash

PCL_EXT_PACKAGES=(
  build-essential cmake pkg-config lld
  libpcl-dev libnanoflann-dev libboost-dev libeigen3-dev nlohmann-json3-dev libexpat1-dev
  libxgboost-dev libcgal-dev
  libgtest-dev libbenchmark-dev
  xvfb xauth
  clang-format python3
)
# scripts/test.sh --fuzz only: clang with its libFuzzer / sanitizer runtimes and OpenMP.
PCL_EXT_FUZZ_PACKAGES=(clang-14 libclang-rt-14-dev libomp-14-dev)

pcl_ext_install_packages() {
  local missing=()
  for p in "${PCL_EXT_PACKAGES[@]}" "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "Installing missing packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q || return 1
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
}

# Start Xvfb when no display is set (VTK here renders through X only); remember its PID.
PCL_EXT_XVFB_PID=""
pcl_ext_start_display() {
  [ -n "${DISPLAY:-}" ] && return 0
  local n
  for n in $(seq 99 140); do
    [ -e "/tmp/.X${n}-lock" ] && continue
    Xvfb ":${n}" -screen 0 1600x1200x24 -nolisten tcp >/dev/null 2>&1 &
    PCL_EXT_XVFB_PID=$!
    sleep 1
    if kill -0 "$PCL_EXT_XVFB_PID" 2>/dev/null; then
      export DISPLAY=":${n}"
      return 0
    fi
  done
  echo "Could not start Xvfb" >&2
  return 1
}

pcl_ext_stop_display() {
  if [ -n "$PCL_EXT_XVFB_PID" ]; then
    kill "$PCL_EXT_XVFB_PID" 2>/dev/null
    wait "$PCL_EXT_XVFB_PID" 2>/dev/null
    PCL_EXT_XVFB_PID=""
  fi
}

pcl_ext_jobs() {
  nproc 2>/dev/null || echo 2
}
