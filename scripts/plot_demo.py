"""`make demo`: velocity magnitude of the throttled pipe with the walls drawn.

    plot_demo.py RUN_DIR      (writes RUN_DIR/velocity.png)

Without matplotlib it says so and exits 0: the demo's metrics stand on their own.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def main():
    run = sys.argv[1] if len(sys.argv) > 1 else "out/demo"
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import numpy  # noqa: F401
    except ImportError as e:
        print(f"plot skipped: matplotlib/numpy not available ({e}); "
              "install python3-matplotlib (scripts/install-deps) for velocity.png")
        return 0
    from plot_throttled_pipe import plot_field

    png = os.path.join(run, "velocity.png")
    plot_field(plt, run, png, "curvsph demo: throttled pipe (NURBS walls, mirror_beta ghosts), |v|")
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
