# Sourced by the gallery scripts. join TARGET IMAGE...: the images left to right, 8 white pixels apart
# (gmic's append pads with 0, so it appends the inverted images).
join() {
  local target=$1 args=()
  shift
  for image in "$@"; do args+=("$image" "8,1,1,3,255"); done
  gmic -v - "${args[@]}" remove[-1] to_rgb mul -1 add 255 append x,0 mul -1 add 255 -o "$target"
}
