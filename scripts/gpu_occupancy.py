"""Throughput of the GPU Lyapunov kernel against the number of members and the threads per
block, N = 5, k = 3 (the settings of `charts bench gpu`), and the CPU lanes on one core.

    python scripts/gpu_occupancy.py          # on a machine with an NVIDIA GPU
"""
import time
import warnings



from charts.geometry.system import RotorSystem
from charts.runs.benchmarks.gpu import cpu_rate, device_flows
from charts.solvers.device import DeviceFlows, cuda_kernel
from charts.solvers.tangent import inner_weights

warnings.simplefilter("ignore")
n, k, T = 5, 3, 50.0
big, cfg, setup = device_flows(n, k, 131072, T, 16)
S = RotorSystem(n)
states = [big._dev[x].copy_to_host() for x in ("Zs", "scs", "speeds")]
big.advance(1)
kern = cuda_kernel(n, k)
try:
    sig = kern.signatures[0]
    print(f"registers per thread {kern.get_regs_per_thread(sig)}, local memory per thread "
          f"{kern.get_local_mem_per_thread(sig)} B", flush=True)
except Exception as e:
    print("kernel attributes:", type(e).__name__, e)
print("| members | threads/block | run s | GPU tu/s |")
print("|---|---|---|---|")
for members in (8448, 16896, 33792, 65536, 131072):
    for threads in (32, 64, 128, 256):
        f = DeviceFlows(S, [a[:members] for a in states], dt=cfg.dt, w=inner_weights(S, cfg.inner),
                        restricted=True, reorth_every=cfg.reorth, project_every=cfg.project,
                        threads=threads)
        f.advance(1)
        runs = []
        for _ in range(2):
            t0 = time.perf_counter()
            f.advance(cfg.total)
            runs.append(time.perf_counter() - t0)
        run = min(runs)
        print(f"| {members} | {threads} | {run:.3f} | {members * T / run:.3g} |", flush=True)
for w, m, t in ((1, 64, 200.0), (16, 1024, 2000.0)):
    wall, rate = cpu_rate(n, k, m, t, w)
    print(f"CPU lanes on {w} core(s): {m} members × T = {t:g}: {wall:.2f} s, {rate:.3g} tu/s "
          f"({rate / w:.3g} per core)", flush=True)
