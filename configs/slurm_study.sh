#!/bin/bash
# A blockfrag study across nodes under Slurm, resumed by resubmitting this same script.
#
#   sbatch configs/slurm_study.sh configs/dam_type_a_study.json [extra blockfrag run options]
#   BLOCKFRAG_LAUNCHER=mpirun sbatch configs/slurm_study.sh ...   (Open MPI's mpirun, not srun)
#
# How the resume works: 120 s before the time limit Slurm sends SIGTERM to this batch shell
# (--signal below), which asks the ranks to stop: each stops after its current scene, rank 0 writes
# the checkpoint OUTPUT.checkpoint and every rank exits with code 4 ("interrupted"). This script
# then requeues the job; the next run of the same command continues from the checkpoint, losing and
# repeating nothing. A kill without warning (node failure) loses only the samples done since the
# last checkpoint (every checkpoint_interval_s). A run against a changed config is refused (exit 2)
# rather than mixing two studies; a study already complete exits 0 at once.
#
#SBATCH --job-name=blockfrag-study
#SBATCH --nodes=2
#SBATCH --ntasks-per-node=32
#SBATCH --time=04:00:00
#SBATCH --output=blockfrag-study-%j.log
#SBATCH --open-mode=append
#SBATCH --requeue
# SIGTERM to the tasks (B: also to this batch shell) 120 s before the limit: time for the ranks to
# finish their current scene and for rank 0 to write the checkpoint before Slurm's SIGKILL.
#SBATCH --signal=B:TERM@120
set -u

study=${1:?usage: sbatch slurm_study.sh STUDY.json [blockfrag run options]}
shift
blockfrag=${BLOCKFRAG:-blockfrag}

# srun starts one rank per task, delivers a SIGTERM to all of them and returns their exit code.
# Open MPI's mpirun forwards a SIGTERM too, but then returns 1 whatever the ranks return; it
# forwards SIGUSR1 and returns the ranks' code, and blockfrag takes SIGUSR1 as it takes SIGTERM.
case ${BLOCKFRAG_LAUNCHER:-srun} in
  srun) launch=(srun --kill-on-bad-exit=0) stop_signal=TERM ;;
  mpirun) launch=(mpirun) stop_signal=USR1 ;;
  *)
    echo "BLOCKFRAG_LAUNCHER must be srun or mpirun (got ${BLOCKFRAG_LAUNCHER})" >&2
    exit 2
    ;;
esac

# The batch shell receives the early SIGTERM (B: above); pass it on to the ranks and keep waiting
# for them to write the checkpoint and exit.
forward_term() {
  echo "$(date -Is) SIGTERM: asking the ranks to checkpoint and stop"
  kill "-$stop_signal" "$run_pid" 2>/dev/null
}
trap forward_term TERM

"${launch[@]}" "$blockfrag" run "$study" "$@" &
run_pid=$!
# wait returns early when the trap fires; wait again for the ranks' own exit code.
wait "$run_pid"
code=$?
if kill -0 "$run_pid" 2>/dev/null; then
  wait "$run_pid"
  code=$?
fi

case $code in
  0) echo "$(date -Is) study complete" ;;
  4)
    echo "$(date -Is) interrupted after a checkpoint: requeueing to resume"
    scontrol requeue "$SLURM_JOB_ID"
    ;;
  2) echo "$(date -Is) refused: bad config or a checkpoint of another config (see above)" ;;
  *) echo "$(date -Is) blockfrag exited with code $code" ;;
esac
exit "$code"
