namespace skinfem {}
