#!/bin/bash
# CPU (user+sys) seconds of the strong-scaling case (58^3 periodic box) on 1 and 2 ranks, at
# two step counts: the difference removes the start-up (generation on every rank).
# Output per run: np, steps, user s, system s, wall s, load. Efficiency in CPU time: (1-rank
# 15-step - 5-step CPU) / (2-rank 15-step - 5-step CPU); it still counts MPI polling.
B=${1:-build/curvsph}
cd "$(dirname "$0")/.."
for np in 1 2; do for st in 5 15; do
  out=${OUT:-/tmp/scaling_cpu_time}/np${np}_st${st}; mkdir -p $out
  /usr/bin/time -f "%U %S %e" -o $out/time.txt mpirun --oversubscribe $( [ "$(id -u)" = 0 ] && echo --allow-run-as-root) -np $np -x OMP_NUM_THREADS=1 -x OMP_WAIT_POLICY=passive --mca mpi_yield_when_idle 1 \
    $B run cases/periodic_box_3d.yaml -q --threads 1 --overwrite --out $out --set resolution.dx=0.017241379310344827 --set time.max_steps=$st --set time.end=100 > $out/log.txt 2>&1
  echo "np=$np steps=$st $(cat $out/time.txt) load=$(cut -d' ' -f1 /proc/loadavg)"
done; done
