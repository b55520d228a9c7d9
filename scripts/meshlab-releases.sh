# Sourced by the scripts that build for the newer MeshLab releases: which Debian suite packages
# each one, and where its root, its source and its build go. 2020.09 is bookworm's, built on
# this machine; its root only tests the package (scripts/package.sh) on a bookworm that has
# never seen the project.
MESHLAB_RELEASES=(2022.02 2025.07)
PACKAGE_RELEASES=(2020.09 "${MESHLAB_RELEASES[@]}")

meshlab_suite() {
  case $1 in
  2020.09) echo bookworm ;;
  2022.02) echo trixie ;;
  2025.07) echo sid ;;
  *)
    echo "unknown MeshLab release $1 (known: ${PACKAGE_RELEASES[*]})" >&2
    return 1
    ;;
  esac
}

# The roots are big (1.6 GB each) and made once per machine: CURVATURE_INPAINT_ROOTS may put
# them outside the checkout; by default they are in its ignored roots/ (the sourcing script
# sets $root to the checkout).
meshlab_root_dir() {
  local suite
  suite=$(meshlab_suite "$1") || return 1
  echo "${CURVATURE_INPAINT_ROOTS:-$root/roots}/$suite"
}
