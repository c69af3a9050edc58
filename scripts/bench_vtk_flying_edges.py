#!/usr/bin/python3
"""Times VTK's vtkFlyingEdges3D on the volumes fm_bench_mesh exported, for the comparison in
docs/marching-cubes.md. Uses Debian's python3-vtk9 (installed on demand with apt-get).

    build-X/bench/fm_bench_mesh --export=/tmp/fm-mesh-volumes
    scripts/bench_vtk_flying_edges.py /tmp/fm-mesh-volumes [--runs 15]

For each volume listed in DIR/volumes.txt (name isovalue), reads DIR/name.mha (float32, the
values fluoromatch meshes), runs vtkFlyingEdges3D at the same isovalue with normals on and
scalars off, with 1 and 2 threads (vtkSMPTools), and prints the mean and median wall time
of several runs (the mean compares with fm_bench_mesh's mean), the fastest run, the median
CPU time of the process (all threads), the wall time of the first (warm-up) run of a new
filter, which allocates its output afresh as a one-off `fluoromatch mesh` does, and the
triangle count.

With --largest-region the timed pipeline is vtkFlyingEdges3D followed by
vtkPolyDataConnectivityFilter keeping the largest region (VTK's way to do what
`fluoromatch mesh --components 1` does; fm_bench_mesh's command_components1 cases).
"""
import argparse
import os
import statistics
import subprocess
import sys
import time


def import_vtk():
    try:
        import vtkmodules.vtkFiltersCore  # noqa: F401
    except ImportError:
        print("installing python3-vtk9 ...", file=sys.stderr)
        sudo = [] if os.geteuid() == 0 else ["sudo"]
        subprocess.run(sudo + ["apt-get", "install", "-y", "-qq", "python3-vtk9"], check=True)
    from vtkmodules.vtkCommonCore import vtkSMPTools
    from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkPolyDataConnectivityFilter
    from vtkmodules.vtkIOImage import vtkMetaImageReader
    return vtkSMPTools, vtkFlyingEdges3D, vtkPolyDataConnectivityFilter, vtkMetaImageReader


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", help="folder written by fm_bench_mesh --export=FOLDER")
    parser.add_argument("--runs", type=int, default=15, help="timed runs per case")
    parser.add_argument("--threads", default="1,2", help="comma-separated thread counts")
    parser.add_argument("--largest-region", action="store_true",
                        help="time flying edges + vtkPolyDataConnectivityFilter (largest region)")
    args = parser.parse_args()
    vtkSMPTools, vtkFlyingEdges3D, vtkConnectivity, vtkMetaImageReader = import_vtk()

    with open(os.path.join(args.folder, "volumes.txt")) as f:
        cases = [line.split() for line in f if line.strip()]
    pipeline = "vtkFlyingEdges3D" + (" + vtkPolyDataConnectivityFilter (largest region)"
                                     if args.largest_region else "")
    print(f"VTK {pipeline}, SMP backend {vtkSMPTools().GetBackend()}")
    print(f"{'volume':24s} {'threads':>7s} {'mean ms':>8s} {'median ms':>10s} {'min ms':>8s} "
          f"{'cpu ms':>8s} {'first ms':>8s} {'triangles':>10s}")
    for name, iso in cases:
        reader = vtkMetaImageReader()
        reader.SetFileName(os.path.join(args.folder, name + ".mha"))
        reader.Update()
        image = reader.GetOutput()
        for threads in [int(t) for t in args.threads.split(",")]:
            vtkSMPTools.Initialize(threads)
            fe = vtkFlyingEdges3D()
            fe.SetInputData(image)
            fe.SetValue(0, float(iso))
            fe.ComputeNormalsOn()
            fe.ComputeGradientsOff()
            fe.ComputeScalarsOff()
            last = fe
            if args.largest_region:
                last = vtkConnectivity()
                last.SetInputConnection(fe.GetOutputPort())
                last.SetExtractionModeToLargestRegion()
            start = time.perf_counter()
            last.Update()  # warm-up
            first = (time.perf_counter() - start) * 1000.0
            times, cpu = [], []
            for _ in range(args.runs):
                fe.Modified()
                start, cpuStart = time.perf_counter(), time.process_time()
                last.Update()
                times.append((time.perf_counter() - start) * 1000.0)
                cpu.append((time.process_time() - cpuStart) * 1000.0)
            triangles = last.GetOutput().GetNumberOfCells()
            print(f"{name:24s} {threads:7d} {statistics.mean(times):8.2f} "
                  f"{statistics.median(times):10.2f} {min(times):8.2f} "
                  f"{statistics.median(cpu):8.2f} {first:8.2f} {triangles:10d}", flush=True)


if __name__ == "__main__":
    main()
