# The rules every study shares (docs/studies.md). The including Snakefile defines `study`, a
# gembem.study.Study, and sets `workdir:` to the study's output directory; each case has its own
# directory CASE/ there. Each rule calls one method of the Study: the logic lives in
# python/gembem/study.py, not here.
#
#   pack:    CASE/grains.csv        rerun when the case's pack_keys change (Snakemake's params trigger)
#   scene:   CASE/scene.yaml        rerun when any column of the case changes, or its packing
#   run:     CASE/status.yaml       gembem; retried (a killed run resumes), a final failure written down
#   measure: CASE/measures.yaml     the status and, for a completed run, the study's measures
#   results: results.csv            one row per case, the missing ones with their status
import os
import sys

import snakemake
from snakemake.common import Mode
from snakemake.exceptions import WorkflowError

import re

# A case wildcard matches the study's case names only (a study may add rules of its own for
# other directories).
wildcard_constraints:
    case="|".join(re.escape(n) for n in study.names())

# Snakemake 7.21 runs a local `run:` job in a Snakemake process of its own, which does not see
# --forcerun/--force/--forceall: a forced job would silently not run. In threads it does.
if workflow.mode == Mode.default:
    _args, _ = snakemake.get_argument_parser().parse_known_args(sys.argv[1:])
    if _args.profile:   # a path from where Snakemake was started (workdir: has moved on), or a name
        _p = os.path.join(workflow.workdir_init, _args.profile)
        _args, _ = snakemake.get_argument_parser(_p if os.path.isdir(_p) else _args.profile).parse_known_args(sys.argv[1:])
    if (_args.forcerun is not None or _args.force or _args.forceall) and not _args.force_use_threads:
        raise WorkflowError("a study forced to re-run needs --force-use-threads (or --profile "
                            "studies/profiles/local): Snakemake 7.21 would skip its forced jobs")

# Cheap steps run where Snakemake runs, not as cluster jobs.
localrules: scene, measure, results


rule results:
    input: expand("{case}/measures.yaml", case=study.names())
    output: "results.csv"
    run:
        rows = study.aggregate(output[0])
        bad = [f"{r['case']} ({r['status']})" for r in rows if r["status"] != "completed"]
        print(f"{output[0]}: {len(rows) - len(bad)} of {len(rows)} cases completed"
              + (f"; not completed: {', '.join(bad)}" if bad else ""))


rule pack:
    output: "{case}/" + study.pack_output
    params: pack=lambda wc: study.pack_params(wc.case)
    resources: runtime=10, mem_mb=1000
    run:
        study.write_pack(wildcards.case, os.path.dirname(output[0]))


rule scene:
    input: lambda wc: ([f"{wc.case}/{study.pack_output}"] if study.pack else []) + study.scene_inputs
    output: "{case}/scene.yaml"
    params: case=lambda wc: study.case(wc.case)
    run:
        study.write_scene(wildcards.case, output[0])


rule run:
    input: "{case}/scene.yaml"
    output: "{case}/status.yaml"
    threads: study.threads
    # Retried by the Snakemake that schedules (each attempt a new job, on a cluster a new
    # submission), not again inside the process that runs a job (Snakemake 7 runs a `run:` job
    # in a Snakemake of its own: retries there would multiply).
    retries: study.retries if workflow.mode == Mode.default else 0
    resources:
        attempt=lambda wc, attempt: attempt,
        runtime=lambda wc, attempt: study.resources["runtime"] * attempt,
        mem_mb=study.resources["mem_mb"]
    run:
        study.run_case(wildcards.case, input[0], output[0], resources.attempt)


rule measure:
    input: "{case}/status.yaml"
    output: "{case}/measures.yaml"
    run:
        study.measure_case(input[0], output[0])


# A job that failed for good (a run killed on its last attempt, a packing that failed): the
# table is still written, those cases 'missing', so that none is dropped without a word.
onerror:
    if workflow.mode == Mode.default:
        study.aggregate("results.csv")
        print("results.csv: written, the cases that did not finish 'missing'")
