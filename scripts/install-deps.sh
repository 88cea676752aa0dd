#!/usr/bin/env bash
# Installs what Stylos needs to build and test on Debian 12 (bookworm). Run as root or with sudo.
# clang and libclang-rt-14-dev: the fuzz harnesses (libFuzzer, ASan, UBSan; docs/fuzzing.md); without them the
# fuzz tests are skipped. qt6-translations-l10n: Qt's own dialogs (file chooser, message boxes) in French.
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends \
  cmake ninja-build g++ pkg-config \
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-translations-l10n \
  libqt6opengl6-dev libgl-dev qt6-svg-dev fonts-dejavu-core poppler-utils \
  libeigen3-dev libglm-dev libopenimageio-dev libnanoflann-dev nlohmann-json3-dev \
  libxxhash-dev libcli11-dev libpugixml-dev \
  libgtest-dev libgmock-dev libbenchmark-dev \
  clang libclang-rt-14-dev \
  xvfb xauth libgl1-mesa-dri
