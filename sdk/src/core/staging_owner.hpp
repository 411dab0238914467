// core/staging_owner.hpp — who owns a staging file or folder, so that only
// provably abandoned staging is ever removed (issue 39).
//
// A staging name is "<target><infix><host>.<boot>.<pidns>.<pid>.<random>":
//   host    gethostname(), letters, digits and '-' only (others become '-');
//   boot    the first 16 hex digits of /proc/sys/kernel/random/boot_id;
//   pidns   the inode of /proc/self/ns/pid (the PID namespace);
//   pid     getpid() in that namespace; random: mkstemp/mkdtemp's 6 characters.
// The owner holds flock(LOCK_EX) on the staging file itself, or on the lock
// file kStagingLockName inside a staging folder, for as long as it lives; the
// kernel drops the lock when the process dies, however it dies.
//
// Staging is abandoned (stagingAbandoned) only when it names this host and
// this boot (one kernel: its flock locks are seen from every PID namespace and
// container sharing the file system) and either its lock can be taken, or it
// names this PID namespace and its pid does not exist. Anything else (another
// host over NFS, another boot, a foreign namespace whose lock is held or not
// there yet, a name of an older version, an unreadable /proc) is kept: a live
// run in a container writing the same output name is never harmed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace onetip {

inline constexpr const char* kStagingLockName = ".onetip-staging.lock";

struct StagingOwner {
  std::string host, boot, pidns;  // boot and pidns are "unknown" when /proc does not say
  long pid = -1;
};

// This process's identity.
StagingOwner thisStagingOwner();
// "<host>.<boot>.<pidns>.<pid>" of this process: the part of its staging names after the infix.
std::string stagingOwnerTag();
// The owner named by "<host>.<boot>.<pidns>.<pid>.<random>" (exactly 6 letters or digits of random), or nothing.
std::optional<StagingOwner> parseStagingOwner(const std::string& after_infix);
// True when `entry` (a staging file, or a folder holding kStagingLockName) owned by `owner` is provably abandoned.
bool stagingAbandoned(const std::filesystem::path& entry, const StagingOwner& owner);

// Takes flock(LOCK_EX|LOCK_NB) on an open descriptor; false when another holds it.
bool lockExclusively(int fd);
// Creates kStagingLockName in `folder` already locked (made under another name, locked, then
// renamed, so the name never shows an unlocked file); returns the descriptor (keep it open to
// hold the lock) or -1 with errno set.
int createFolderLock(const std::string& folder);

}  // namespace onetip
