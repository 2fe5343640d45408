// Deliberately broken .geo (unterminated statement) for the reader's error test.
Point(1) = {0, 0, 0
