# Sourced by the set-up scripts: debian_mirror prints the Debian mirror this machine already
# installs bookworm from, as its own apt sources name it (nothing else names a mirror).
debian_mirror_from_lists() {
  apt-get indextargets --format '$(REPO_URI) $(RELEASE) $(TARGET_OF)' 2>/dev/null |
    awk '$2 == "bookworm" && $3 == "deb" { print $1; exit }'
}

debian_mirror() {
  local mirror
  mirror=$(debian_mirror_from_lists)
  if [ -z "$mirror" ]; then
    # apt knows its sources' index targets only once it has fetched their lists.
    echo "setup: apt-get update" >&2
    if [ "$(id -u)" -eq 0 ]; then apt-get update -qq; else sudo apt-get update -qq; fi
    mirror=$(debian_mirror_from_lists)
  fi
  if [ -z "$mirror" ]; then
    echo "setup: no bookworm entry in this machine's apt sources to take Debian's packages from" >&2
    return 1
  fi
  echo "$mirror"
}
