#!/bin/bash
# Background-pressure sensitivity of the cylinder_lattice low-resolution runs (findings.md,
# "Tensile events"): the case's Tait EOS with p0 = B = rho0 c0^2 / gamma (p > 0 at every
# density) instead of the case's p0 = 2.0, at the study's dx (the coarsest the
# density-preserving map admits), t_end = 10, one OpenMP thread per run.
# Usage: scripts/cylinder_lattice_p0_sweep.sh OUT.csv "MAPS" "V0S" [SEEDS]
#   e.g. scripts/cylinder_lattice_p0_sweep.sh /tmp/sweep.csv "density_preserving" "0.75 0.70" 20
# Resumable: rows already in OUT.csv are skipped.
set -eu
csv=$1
maps=$2
v0s=$3
seeds=${4:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/curvsph
p0=8.035714285714286  # 1 * 7.5^2 / 7
dx=0.03183071913928631
[ -f "$csv" ] || echo "map,v0,seed,t_max,event" > "$csv"
tmp=$(mktemp -d)
for v0 in $v0s; do
  for map in $maps; do
    for s in $(seq 1 "$seeds"); do
      grep -q "^$map,$v0,$s," "$csv" && continue
      out=$tmp/run
      "$bin" run "$root/cases/cylinder_lattice.yaml" --out "$out" --set boundary.map="$map" \
        --set resolution.dx=$dx --set forcing.drive.v0="$v0" --set setup.random_seed="$s" \
        --set time.end=10 --set eos.p0=$p0 --threads 1 > "$out.log" 2>&1 || true
      ev=$(grep -o 'UNSTABLE[^(]*' "$out.log" | head -1 | tr ',' ';' || true)
      tm=$(grep -o '"t_max": [0-9.e+-]*' "$out/metrics.json" | awk '{print $2}')
      echo "$map,$v0,$s,$tm,$ev" >> "$csv"
      rm -rf "$out" "$out.log"
    done
  done
done
rmdir "$tmp" 2>/dev/null || true
