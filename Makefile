# qdot: thin wrapper over CMake.  `make demo` and `make test` do all set-up.
PREFIX ?= /usr/local
JOBS   ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE  ?= cmake

.PHONY: all deps build demo test test-builds test-asan test-tsan bench install clean

all: build

build/Makefile:
	./scripts/deps.sh build
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQDOT_TESTS=ON

build: build/Makefile
	$(CMAKE) --build build -j $(JOBS)

demo:
	./scripts/deps.sh build
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQDOT_TESTS=OFF
	$(CMAKE) --build build -j $(JOBS) --target qdot_cli qdot
	./build/qdot eom examples/double_pendulum.qd
	./build/qdot modes examples/double_pendulum.qd
	./build/qdot simulate examples/double_pendulum.qd --t-end 1000 --rtol 1e-12 --initial "theta1=pi/2, theta2=pi/2" --out /dev/null

# Every test twice: a normal build, then AddressSanitizer + UBSan (any report
# fails); every tree with warnings as errors (QDOT_WERROR, never forced on users).
test:
	./scripts/deps.sh test
	$(CMAKE) -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQDOT_TESTS=ON -DQDOT_WERROR=ON
	$(CMAKE) --build build -j $(JOBS)
	cd build && ctest --output-on-failure -j $(JOBS)
	$(MAKE) test-builds
	$(MAKE) test-asan
	$(MAKE) test-tsan

# Built, not run: what a user's plain `cmake -DCMAKE_BUILD_TYPE=Release` makes
# (-O3) with GCC and with clang, the tests included, warnings as errors, so
# that a warning only one compiler or -O level sees cannot come back.
test-builds:
	$(CMAKE) -S . -B build-gcc-release -DCMAKE_C_COMPILER=gcc -DCMAKE_BUILD_TYPE=Release \
	  -DQDOT_TESTS=ON -DQDOT_WERROR=ON
	$(CMAKE) --build build-gcc-release -j $(JOBS)
	$(CMAKE) -S . -B build-clang-release -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=Release \
	  -DQDOT_TESTS=ON -DQDOT_WERROR=ON
	$(CMAKE) --build build-clang-release -j $(JOBS)

test-asan:
	$(CMAKE) -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DQDOT_SANITIZE=ON -DQDOT_TESTS=ON \
	  -DQDOT_WERROR=ON
	$(CMAKE) --build build-asan -j $(JOBS)
	cd build-asan && ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
	  ctest --output-on-failure -j $(JOBS) -LE nosan

# Two threads sharing one compiled system under ThreadSanitizer (any report
# fails): only the library and that test are built.
test-tsan:
	$(CMAKE) -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQDOT_TSAN=ON -DQDOT_TESTS=ON \
	  -DQDOT_WERROR=ON
	$(CMAKE) --build build-tsan -j $(JOBS) --target sim_test_threads
	TSAN_OPTIONS=halt_on_error=1:exitcode=66 ./build-tsan/tests/sim_test_threads
	# Lyapunov exponents: two threads on one qd_lyap (tests/lyap/test_threads.c)
	$(CMAKE) --build build-tsan -j $(JOBS) --target lyap_test_threads
	TSAN_OPTIONS=halt_on_error=1:exitcode=66 ./build-tsan/tests/lyap_test_threads
	# qdot sweep's worker pool (issue 21): the runs of one sweep on 2 threads
	$(CMAKE) --build build-tsan -j $(JOBS) --target sweep_test_sweep
	TSAN_OPTIONS=halt_on_error=1:exitcode=66 ./build-tsan/tests/sweep_test_sweep

bench:
	./scripts/deps.sh bench
	$(CMAKE) -S . -B build-bench -DCMAKE_BUILD_TYPE=Release -DQDOT_TESTS=OFF -DQDOT_BENCH=ON
	$(CMAKE) --build build-bench -j $(JOBS)
	./bench/run_kernel.sh build-bench
	/usr/bin/python3 bench/run_pendulum.py build-bench
	/usr/bin/python3 bench/run_hamiltonian.py build-bench
	/usr/bin/python3 bench/run_modes.py build-bench
	/usr/bin/python3 bench/run_jit.py build-bench
	/usr/bin/python3 bench/run_rhs.py build-bench
	/usr/bin/python3 bench/run_simulate.py build-bench
	/usr/bin/python3 bench/run_speeds.py build-bench
	/usr/bin/python3 bench/run_taylor.py build-bench
	if [ -x build-bench/bench/quad_bench ]; then ./build-bench/bench/quad_bench; fi
	./build-bench/bench/run_symmetry
	/usr/bin/python3 bench/run_sweep.py build-bench
	/usr/bin/python3 bench/run_sweep_mpi.py build-bench
	/usr/bin/python3 bench/run_parse.py build-bench
	/usr/bin/python3 bench/run_startup.py build-bench
	/usr/bin/python3 bench/run_python.py build-bench

install: build
	$(CMAKE) --install build --prefix $(PREFIX)

clean:
	rm -rf build build-asan build-tsan build-bench build-gcc-release build-clang-release
