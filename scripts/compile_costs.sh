#!/usr/bin/env bash
# What including the library costs a user's program (docs/results/compile-costs.md): the
# preprocessed non-blank lines of headers, and the compile time of the README's C++ example
# against a program of the same size that includes only <Eigen/Dense>, one compile at a time
# (run it on an otherwise idle machine). Needs a configured build folder for its include/ links.
#   bash scripts/compile_costs.sh [build folder, default build]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
flags=(-std=c++17 -DEIGEN_USE_BLAS -DDDB_USE_LAPACK -I "$build/include" -isystem /usr/include/eigen3)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| header | non-blank preprocessed lines |"
echo "|---|---|"
for header in ddb/ddb.h ddb/integrators/methods/method_table.h ddb/integrators/methods/reference.h \
              ddb/groups/so3.h ddb/groups/se3.h ddb/groups/son.h ddb/groups/sun.h Eigen/Dense; do
  lines=$(echo "#include <$header>" | g++ -E -P "${flags[@]}" -x c++ - | grep -cv '^\s*$')
  echo "| \`<$header>\` | $lines |"
done

# The README's example, as a user copies it.
sed -n '/^```cpp/,/^```/p' README.md | sed '1,/^```cpp/{/^```cpp/d}' | sed '/^```/,$d' > "$work/readme.cc"
# The same loop with Eigen alone: explicit Euler on the rigid body, printed as the example does.
cat > "$work/eigen_only.cc" <<'PROGRAM'
#include <Eigen/Dense>

#include <cstdio>

int main() {
  const Eigen::Vector3d inverse_inertia(1.0, 1.0 / 1.3, 2.0);
  Eigen::Vector3d m(0.0, 0.065, 0.5);
  for (long k = 0; k <= 300; ++k) {
    if (k % 100 == 0)
      std::printf("t = %4.1f  H = %.15f  |M| = %.15f\n", 0.1 * double(k),
                  0.5 * m.dot(inverse_inertia.cwiseProduct(m)), m.norm());
    const Eigen::Vector3d omega = inverse_inertia.cwiseProduct(m);
    m += 0.1 * (m.cross(omega) + 0.5 * m.cross(m.cross(omega)));
  }
}
PROGRAM
echo
echo "| program (g++ -O2 -c) | seconds |"
echo "|---|---|"
for program in readme eigen_only; do
  /usr/bin/time -f "%e" -o "$work/$program.time" g++ -O2 "${flags[@]}" -c "$work/$program.cc" \
    -o "$work/$program.o"
  echo "| $program | $(cat "$work/$program.time") |"
done
