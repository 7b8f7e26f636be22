# A timing fixture: the project installs hyperfine only.
packages=(
  hyperfine   # timing
)
