"""Results on disk: NetCDF save and load (`charts.io.archive`), the settings and words a
file carries (`charts.io.file_settings`, `charts.io.result_words`), and the atomic write that
never leaves a half-written file (`charts.io.atomic`)."""
