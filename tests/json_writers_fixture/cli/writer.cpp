// A writer that dumps JSON itself: tests/json_writers.py must name line 3.
void write(const Json& j, std::ostream& out) {
    out << j.dump(2) << '\n';
}
