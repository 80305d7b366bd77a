# The RTL file list rtl/rpu.f for the shell scripts (scripts/formal.sh, scripts/yosys_report.sh):
# source this file, then `rpu_rtl_read ROOT` sets
#   rtl_sources  every source file of the list, absolute paths, in the list's order
#   rtl_incdirs  its include directories (+incdir+ lines), absolute paths
# and fails (status 1, a message naming the entry) when the list names a file that does not exist.
# Format (rtl/rpu.f's header): a path relative to rtl/ per line, +incdir+DIR, // comments.
rpu_rtl_read() {
  local rtl=$1/rtl line
  local list=$rtl/rpu.f
  rtl_sources=()
  rtl_incdirs=()
  [[ -r $list ]] || { echo "$list: cannot read the RTL file list" >&2; return 1; }
  while IFS= read -r line || [[ -n $line ]]; do
    line=${line%%//*}
    line=${line#"${line%%[![:space:]]*}"}
    line=${line%"${line##*[![:space:]]}"}
    case $line in
      '') continue ;;
      +incdir+*)
        line=$rtl/${line#+incdir+}
        [[ -d $line ]] || { echo "$list: no directory $line" >&2; return 1; }
        rtl_incdirs+=("$line") ;;
      [-+]*)
        echo "$list: unsupported option line '$line'" >&2
        return 1 ;;
      *)
        line=$rtl/$line
        [[ -f $line ]] || { echo "$list: no file $line" >&2; return 1; }
        rtl_sources+=("$line") ;;
    esac
  done <"$list"
}
