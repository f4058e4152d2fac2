camera { location 0 look_at 0 }
