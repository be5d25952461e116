# Scenes derived from another by their keys, for the shell tests (sourced): a test names the keys
# it changes, so an edit of a key the scene does not have stops the test instead of silently
# running another case (as a sed over the YAML text would).
#   scene_edit IN.yaml -o OUT.yaml [--set KEY=VALUE] [--add KEY=VALUE] [--delete KEY] ...
# is `python3 -m gembem scene` (docs/python.md): KEY dotted, list items by index
# (loading.1.host_load.steps), VALUE YAML flow ('{kn: 1000, kt: 500}'); --set replaces a value IN
# has, --add creates one it has not, --delete removes one it has; the edits apply in the order
# given; OUT's file names (host.mesh, grains.file, initial_state) are absolute unless set here.
# A refused edit prints the key and exits the test with status 2.
gb_scene_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
scene_edit() {
  PYTHONPATH="$gb_scene_root/python" /usr/bin/python3 -m gembem scene "$@" \
    || { echo "scene_edit $*: refused (exit status $?)" >&2; exit 2; }
}
