#!/usr/bin/env bash
# Runs commands in a clean Debian 12 root, the way a CI service runs a job in
# a fresh debian:12 container: a minimal bookworm root (debootstrap, minbase),
# the committed project (git archive HEAD: nothing from the working tree or
# the host's build) in /root/shadelab, and each command run there as root with
# chroot and an empty environment.
#
#   bash scripts/clean-root.sh [--name NAME] [--share DIR] [--fresh] COMMAND ...
#
#   --name NAME   the root's name (default: readme); its base is cached
#   --share DIR   a host folder mounted at /root/share inside the root, to
#                 bring files in or out (a .deb, say)
#   --fresh       start cold: rebuild the cached base root and forget the
#                 downloaded packages
#
# The base root is built once and cached in $SHADELAB_ROOT_CACHE (default
# /var/cache/shadelab); each run works on a throw-away overlay of it, so no
# run sees another's files. Downloaded .deb files are cached there too:
# apt still resolves and installs everything, it just does not download a
# package twice. Each command's output goes to a log beside the cache; the
# script prints one line per command with its exit status and time, and the
# log's tail when a command fails. It needs root (debootstrap, mount, chroot).
set -euo pipefail
cd "$(dirname "$0")/.."

name=readme
share=
fresh=
while [ $# -gt 0 ]; do
  case "$1" in
    --name) name=$2; shift 2 ;;
    --share) share=$(realpath "$2"); shift 2 ;;
    --fresh) fresh=1; shift ;;
    --) shift; break ;;
    -*) echo "clean-root: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
if [ $# -eq 0 ]; then
  echo "clean-root: no command to run (usage: clean-root.sh [--name NAME] [--share DIR] [--fresh] COMMAND ...)" >&2
  exit 2
fi
if [ "$(id -u)" -ne 0 ]; then
  echo "clean-root: needs root (debootstrap, mount, chroot)" >&2
  exit 1
fi

cache=${SHADELAB_ROOT_CACHE:-/var/cache/shadelab}
base=$cache/roots/bookworm-minbase
debs=$cache/apt-archives
logs=$cache/logs
run=$cache/runs/$name
mkdir -p "$cache/roots" "$debs/partial" "$logs"

bash scripts/install-deps.sh --only debootstrap

# The mirror the host's apt uses, so the root reaches the same archive.
mirror=$(sed -n 's/^URIs: *//p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n 1)
mirror=${mirror:-http://deb.debian.org/debian}

if [ -n "$fresh" ]; then
  rm -rf "$base" "$debs"
  mkdir -p "$debs/partial"
fi
if [ ! -f "$base/.complete" ]; then
  start=$SECONDS
  rm -rf "$base"
  if ! debootstrap --variant=minbase bookworm "$base" "$mirror" > "$logs/debootstrap.log" 2>&1; then
    echo "clean-root: debootstrap failed (log $logs/debootstrap.log):" >&2
    tail -n 20 "$logs/debootstrap.log" >&2
    exit 1
  fi
  # Like the debian:12 image: the security and update suites as well.
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    rm -f "$base/etc/apt/sources.list"
    cp /etc/apt/sources.list.d/debian.sources "$base/etc/apt/sources.list.d/"
  fi
  rm -rf "$base/var/cache/apt/archives"/*.deb
  # As in Debian's container images: the root is thrown away after the run,
  # so dpkg need not fsync every file it unpacks (most of an install's time).
  echo force-unsafe-io > "$base/etc/dpkg/dpkg.cfg.d/unsafe-io"
  touch "$base/.complete"
  echo "clean-root: built the base root in $((SECONDS - start)) s ($base)"
fi

# A throw-away overlay of the base: lower = base, upper = this run's changes.
# The cached packages are hard-linked into the upper layer before it is
# mounted, and the ones this run downloaded are linked back afterwards: no
# copying, and no apt lock shared with a run under another --name.
archives=var/cache/apt/archives
teardown() {
  umount -R "$run/merged" 2>/dev/null || umount -R -l "$run/merged" 2>/dev/null || true
  if [ -d "$run/upper/$archives" ]; then
    find "$run/upper/$archives" -maxdepth 1 -name '*.deb' -type f -links 1 -exec ln -t "$debs" {} + || true
  fi
  rm -rf "$run"
}
teardown
trap teardown EXIT
mkdir -p "$run/upper/$archives/partial" "$run/work" "$run/merged"
find "$debs" -maxdepth 1 -name '*.deb' -type f -exec ln -t "$run/upper/$archives" {} +
mount -t overlay overlay -o "lowerdir=$base,upperdir=$run/upper,workdir=$run/work" "$run/merged"
root=$run/merged

mount -t proc proc "$root/proc"
mount --rbind /sys "$root/sys"
mount --make-rslave "$root/sys"
# The root's own /dev: the host's /dev/null may be root-only, and apt drops to
# the _apt user inside the root.
mount -t tmpfs -o mode=755 dev "$root/dev"
while read -r node major minor; do
  mknod -m 666 "$root/dev/$node" c "$major" "$minor"
done <<'NODES'
null 1 3
zero 1 5
full 1 7
random 1 8
urandom 1 9
tty 5 0
NODES
ln -s /proc/self/fd "$root/dev/fd"
ln -s /proc/self/fd/0 "$root/dev/stdin"
ln -s /proc/self/fd/1 "$root/dev/stdout"
ln -s /proc/self/fd/2 "$root/dev/stderr"
mkdir -p "$root/dev/shm" "$root/dev/pts"
mount -t tmpfs -o mode=1777 shm "$root/dev/shm"
# A private pseudo-terminal instance (dpkg logs through one); optional.
if mount -t devpts -o newinstance,ptmxmode=0666,mode=620 devpts "$root/dev/pts" 2>/dev/null; then
  ln -s pts/ptmx "$root/dev/ptmx"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
if [ -n "$share" ]; then
  mkdir -p "$root/root/share"
  mount --bind "$share" "$root/root/share"
fi

mkdir -p "$root/root/shadelab"
git archive --format=tar HEAD | tar -x -C "$root/root/shadelab"

status=0
i=0
for cmd in "$@"; do
  i=$((i + 1))
  log=$logs/$name-$i.log
  start=$SECONDS
  if chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
      /bin/bash -c "cd /root/shadelab && $cmd" < /dev/null > "$log" 2>&1; then
    rc=0
  else
    rc=$?
  fi
  echo "clean-root ($name): exit $rc in $((SECONDS - start)) s: $cmd (log $log)"
  # What ctest concluded, if the command ran it.
  grep -E '^[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$log" || true
  if [ "$rc" -ne 0 ]; then
    tail -n 40 "$log"
    status=$rc
    break
  fi
done
exit "$status"
