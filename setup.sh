#!/usr/bin/env bash
# ServoBench set-up: installs what is missing (Debian 12 / Ubuntu 24.04), builds, then runs the
# GUI on simulated servos (`./setup.sh run`) or the whole test suite (`./setup.sh test`).
set -euo pipefail

cd "$(dirname "$0")"

packages=(
    g++ cmake ninja-build pkg-config lld
    qt6-base-dev qt6-serialport-dev qt6-charts-dev libqt6opengl6-dev libgl-dev libxkbcommon-dev
    qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
    qt6-translations-l10n
)

usage() {
    echo "usage: ./setup.sh run            build and start ServoBench on a simulated servo"
    echo "       ./setup.sh test           build and run every test (offscreen)"
    echo "       ./setup.sh test --sanitize  the same with AddressSanitizer + UBSan"
    echo "       ./setup.sh build          only install what is missing and build"
    echo "       ./setup.sh package        build the Debian package into build/"
    echo "       ./setup.sh package --check  the same, then install it and check what it installed"
    echo "       ./setup.sh bench          build and run every benchmark (bench/run-all), GUI ones under Xvfb"
}

install_missing() {
    local missing=()
    for package in "${packages[@]}"; do
        if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$package")
        fi
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "setup: installing ${missing[*]}"
    as_root apt-get update
    DEBIAN_FRONTEND=noninteractive as_root apt-get install -y --no-install-recommends "${missing[@]}"
}

as_root() {
    if [ "$(id -u)" -eq 0 ]; then
        "$@"
    else
        command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 1; }
        sudo "$@"
    fi
}

# Installs the package just built and checks it: the installed servoctl runs, and the desktop
# entry and AppStream metainfo pass their validators.
check_package() {
    local deb=$1
    # dpkg alone, as a user would; apt brings in what it depends on if something is missing.
    as_root dpkg -i "$deb" || DEBIAN_FRONTEND=noninteractive as_root apt-get install -f -y
    /usr/bin/servoctl --version
    test -x /usr/bin/servobench && test -x /usr/bin/servosim
    desktop-file-validate /usr/share/applications/io.github.servobench.ServoBench.desktop
    appstreamcli validate --no-net /usr/share/metainfo/io.github.servobench.ServoBench.metainfo.xml
    test -f /usr/lib/udev/rules.d/70-servobench.rules
    test -f /usr/share/man/man1/servoctl.1 && test -f /usr/share/man/man1/servosim.1
    # Qt's own buttons and dialogs in the window's language come with the package's dependency.
    test -f /usr/share/qt6/translations/qtbase_zh_CN.qm
    bash -c 'source /usr/share/bash-completion/completions/servoctl && complete -p servoctl'
    echo "setup: $deb installed and checked"
}

# Optimised, with line tables only (-g1): backtraces and sanitizer reports name file and line, and
# the build takes a third less time than with full debug information.
build() {
    local dir=$1; shift
    cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
        -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DSERVOBENCH_UNITY_BUILD=ON "$@"
    cmake --build "$dir" --parallel "$(nproc)"
}

command=${1:-}
shift || true
case "$command" in
    run)
        install_missing
        build build
        exec ./build/app/servobench --demo "$@"
        ;;
    test)
        install_missing
        dir=build
        # The suite runs no benchmark program (./setup.sh bench builds them).
        flags=(-DSERVOBENCH_BENCH_PROGRAMS=OFF)
        if [ "${1:-}" = "--sanitize" ]; then
            dir=build-sanitize
            # -Og: the same checks as -O1 in two thirds of its compile time, and the suite,
            # which mostly waits on timers and the simulated servos, runs as fast.
            # The benchmark programs are left out: the suite does not run them.
            flags=(-DSERVOBENCH_SANITIZE=ON -DSERVOBENCH_BENCH_PROGRAMS=OFF
                   -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-Og -g1 -DNDEBUG")
            export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
            export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
        fi
        build "$dir" "${flags[@]}"
        # The tests mostly wait (on timers and on the simulated servos' replies: the cores are
        # busy a sixth of the time with three per core). Those that must run alone say so
        # (RUN_SERIAL).
        ctest --test-dir "$dir" --output-on-failure --parallel "$(( $(nproc) * 3 ))" --timeout 600
        ;;
    build)
        install_missing
        build build
        ;;
    bench)
        # The GUI figures count only from a real X server (the offscreen platform draws
        # nothing): Xvfb gives the benchmarks one, through xvfb-run.
        packages+=(xvfb xauth)
        install_missing
        build build -DSERVOBENCH_BENCH_PROGRAMS=ON
        exec bench/run-all build "$@"
        ;;
    package)
        # dpkg-shlibdeps (dpkg-dev, which needs file) works out the package's dependencies.
        packages+=(dpkg-dev file)
        [ "${1:-}" = "--check" ] && packages+=(appstream desktop-file-utils)
        install_missing
        build build
        (cd build && cpack)
        deb=$(ls -t build/servobench_*.deb | head -1)
        echo "setup: built $deb"
        if [ "${1:-}" = "--check" ]; then
            check_package "$PWD/$deb"
        fi
        ;;
    *)
        usage
        exit 2
        ;;
esac
