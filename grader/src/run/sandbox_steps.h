#pragma once
// The steps of entering the sandbox (sandbox.h), internal to grader/src/run/: sandbox.cpp plans the walls and enters
// them, building the new root with sandbox_root.cpp; the namespace's first process, which outlives the fork of the
// student's, is sandbox_init.cpp. Each step says why it failed in `why`, for the report channel.
#include "grader/src/run/sandbox.h"

#include <string>
#include <sys/types.h>

namespace gsv {

// `why` = "<what>: <the system's error>"; false, so that a step returns sandbox_fail(why, "cannot ...").
bool sandbox_fail(std::string& why, const std::string& what);

// In the first process of the new PID namespace, inside the new mount namespace: the new root, then pivot into it.
bool build_root(const SandboxPlan& plan, std::string& why);

// The namespace's first process is a fork of the grader, so /proc/1/cmdline would show the grader's command line
// (a --seed among it) to student code. Its argument and environment memory is zeroed, and it is made undumpable,
// which closes its other /proc files to the student's process.
void scrub_grader_traces();
// Ends this process as `status` ended its child: the same exit code, or the same signal.
[[noreturn]] void exit_as(int status);
// Waits for `pid` to end, through interruptions: its wait status.
int wait_for(pid_t pid);
// What the working folder holds now, from inside (it goes with the namespace, so only here can it be seen), said on the
// report channel as "<word> BYTES FILES FULL"; just "<word>" where the folder is not the namespace's own.
void say_folder(const SandboxPlan& plan, const char* word);
// The namespace's first process while a served lab runs (ServedProcess, process.h): it waits for the student's process
// and answers the grader's commands on the report channel, a byte each. 'p' stops every other process of the namespace
// and says "paused" with what the working folder holds once each of their threads has stopped, so nothing of the
// student's runs between its cases: not while the grader judges, the reference renders or anything is timed, and no
// message can reach the hand-in socket then. 'r' lets them run again. The grader gone (its end closed), all end.
int answer_commands(const SandboxPlan& plan, pid_t student);

}  // namespace gsv
